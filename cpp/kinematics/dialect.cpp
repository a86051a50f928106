#include "kinematics/dialect.hpp"

#include "common/error.hpp"

namespace hsm::kinematics {

std::string dialectName(Dialect dialect) {
  switch (dialect) {
    case Dialect::LinuxCnc: return "linuxcnc";
    case Dialect::Grbl: return "grbl";
    case Dialect::Siemens840D: return "siemens-840d";
    case Dialect::Fanuc: return "fanuc";
    case Dialect::Haas: return "haas";
  }
  return "?";
}

Dialect dialectFromName(const std::string& name, const std::string& origin) {
  for (const Dialect d : {Dialect::LinuxCnc, Dialect::Grbl, Dialect::Siemens840D, Dialect::Fanuc, Dialect::Haas})
    if (dialectName(d) == name) return d;
  throw InputError(origin + ": dialect \"" + name + "\" is unknown: use linuxcnc, grbl, siemens-840d, fanuc or haas");
}

}  // namespace hsm::kinematics
