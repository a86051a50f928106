// Feed-rate simulation throughput, measured in one run: reading alone, reading + simulating with the 840D
// model (summary only), and the heap in use while simulating 1 M and 4 M blocks (it must not grow); then the same
// moves as a 5-axis TRAORI program (A and C turning under a degree per block) on the A/C trunnion model.
// Then LinuxCNC's language: the plain program on the LinuxCNC model, and a program whose moves come from an
// O-word loop with parameters and expressions.
// Then Fanuc's: the plain program on the Fanuc preset (its lines kept for jumps back), and a Macro B WHILE loop;
// and the 840D's WHILE loop.
// Targets: at least 2,500,000 blocks/s end to end on one core (3 axes), 1,500,000 (5 axes), 1,000,000 from
// loops. Times are the process's CPU time.
// Run: build/bin/bench_feedsim [five-axis [blocks]]   (five-axis: only the 5-axis program, e.g. under perf)
#include "kinematics/simulation.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <cmath>
#include <cstdio>
#include <malloc.h>
#include <sstream>

using namespace hsm::kinematics;

namespace {
// A finishing-like program: zigzag passes of 0.2-0.8 mm G1 blocks along gently curved lines, 0.4 mm apart.
std::string finishingProgram(long blocks, bool fiveAxis = false) {
  std::string text = "G90 G17 G21\nCYCLE832(0.01,_ORI_FINISH,1)\n";
  text += fiveAxis ? "TRAORI\nG0 X0 Y0 Z5 A10 C0\nG1 Z0 F6000\n" : "G0 X0 Y0 Z5\nG1 Z0 F6000\n";
  text.reserve(static_cast<size_t>(blocks) * 32);
  char line[96];
  double x = 0.0, y = 0.0;
  int direction = 1;
  for (long i = 0; i < blocks; ++i) {
    x += direction * (0.2 + 0.6 * (0.5 + 0.5 * std::sin(i * 0.37)));
    if (x > 140.0 || x < 0.0) {
      direction = -direction;
      y += 0.4;
    }
    const double z = -0.5 * std::sin(x / 20.0) * std::cos(y / 15.0);
    if (fiveAxis)  // the tool leans 5-15° and turns round slowly, as a 5-axis finishing pass does
      std::snprintf(line, sizeof line, "X%.4f Y%.4f Z%.4f A%.3f C%.3f\n", x, y + 0.8 * std::sin(x / 9.0), z,
                    10.0 + 5.0 * std::sin(x / 30.0), 0.002 * i);
    else
      std::snprintf(line, sizeof line, "X%.4f Y%.4f Z%.4f\n", x, y + 0.8 * std::sin(x / 9.0), z);
    text += line;
  }
  return text + "M30\n";
}

// The same kind of zigzag, each move computed in a LinuxCNC while loop (four lines run per block).
std::string loopProgram(long blocks) {
  return "G90 G17 G21\nG0 X0 Y0 Z5\nG1 Z0 F6000\n#<i> = 0\n"
         "o1 while [#<i> LT " + std::to_string(blocks) + "]\n"
         "G1 X[[#<i> MOD 700] * 0.2] Y[FIX[#<i> / 700] * 0.4] Z[-0.5 * SIN[#<i> * 0.5]]\n"
         "#<i> = [#<i> + 1]\no1 endwhile\nM30\n";
}

// The loop of loopProgram in Fanuc's Macro B.
std::string macroLoopProgram(long blocks) {
  return "%\nO0001\nG90 G17 G21\nG0 X0 Y0 Z5\nG1 Z0 F6000\n#1=0\nWHILE [#1 LT " + std::to_string(blocks) +
         "] DO 1\nG1 X[[#1 MOD 700]*0.2] Y[FIX[#1/700]*0.4] Z[-0.5*SIN[#1*0.5]]\n#1=#1+1\nEND 1\nM30\n%\n";
}

// The loop of loopProgram in the 840D's language (SIN in degrees: 0.5 rad is 28.6479 deg).
std::string siemensLoopProgram(long blocks) {
  return "G90 G17 G71\nG0 X0 Y0 Z5\nG1 Z0 F6000\nDEF INT I=0\nWHILE I<" + std::to_string(blocks) +
         "\nG1 X=(I MOD 700)*0.2 Y=TRUNC(I/700)*0.4 Z=-0.5*SIN(I*28.6479)\nI=I+1\nENDWHILE\nM30\n";
}

// CPU seconds of this process (best of three): on a machine other work shares, the wall clock counts the time
// the scheduler gives them too; the process's own CPU time stays near what a quiet core gives.
double cpuNow() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double seconds(const std::function<void()>& work) {
  double best = 1e300;
  for (int repeat = 0; repeat < 3; ++repeat) {
    const double start = cpuNow();
    work();
    best = std::min(best, cpuNow() - start);
  }
  return best;
}

size_t heapInUse() { return mallinfo2().uordblks; }

// The most heap in use above the start while the program is simulated, MB.
double peakHeapMb(std::istream& program, const MachineModel& machine) {
  const size_t before = heapInUse();
  size_t peak = before;
  SimulationOptions options;
  options.onProgress = [&](long) { peak = std::max(peak, heapInUse()); };
  simulate(program, machine, {}, options);
  return (peak - before) / 1e6;
}

void fiveAxis(long blocks, const SimulationSummary& threeAxis, double threeAxisTime) {
  const MachineModel trunnion = loadMachine("mikron-ucp710-ac-840d", {HSM_MACHINES_DIR});
  const std::string five = finishingProgram(blocks, true);
  SimulationSummary fiveSummary;
  const double fiveTime = seconds([&] {
    std::istringstream stream(five);
    fiveSummary = simulate(stream, trunnion).summary;
  });
  std::printf("5-axis read + simulate: %5.2f s  %10.0f blocks/s  (A/C trunnion, TRAORI)", fiveTime,
              fiveSummary.blockCount / fiveTime);
  if (threeAxisTime > 0.0)
    std::printf(", %.2f x the 3-axis rate", (fiveSummary.blockCount / fiveTime) / (threeAxis.blockCount / threeAxisTime));
  double all = 0.0;
  for (double t : fiveSummary.limitTime) all += t;
  std::printf("\n5-axis simulated time %.1f s; limits:", fiveSummary.totalTime);
  for (int k = 0; k < kSpeedLimitCount; ++k)
    if (fiveSummary.limitTime[k] > 0.0)
      std::printf(" %s %.1f %%", speedLimitName(static_cast<SpeedLimit>(k)), 100.0 * fiveSummary.limitTime[k] / all);
  std::printf("\n");
}
}  // namespace

int main(int argc, char** argv) {
  const long blocks = 2000000;
  if (argc > 1 && std::strcmp(argv[1], "five-axis") == 0) {
    char* end = nullptr;
    const long asked = argc > 2 ? std::strtol(argv[2], &end, 10) : blocks;
    if (argc > 2 && (end == argv[2] || *end != '\0' || asked < 1 || asked > 20000000)) {
      std::fprintf(stderr, "bench_feedsim five-axis: blocks '%s' must be a whole number from 1 to 20000000 "
                   "(the program text takes about 45 bytes a block)\n", argv[2]);
      return 2;
    }
    fiveAxis(asked, {}, 0.0);
    return 0;
  }
  const MachineModel machine = loadMachine("mikron-ucp710-840d", {HSM_MACHINES_DIR});
  const std::string program = finishingProgram(blocks);

  long read = 0;
  const double readTime = seconds([&] {
    std::istringstream stream(program);
    GcodeReader reader(stream);
    Block b;
    read = 0;
    while (reader.next(b)) ++read;
  });
  SimulationSummary summary;
  const double simulateTime = seconds([&] {
    std::istringstream stream(program);
    summary = simulate(stream, machine).summary;
  });
  std::printf("program: %ld G1 blocks of 0.2-0.8 mm, %.0f MB of G-code\n", read, program.size() / 1e6);
  std::printf("read only:           %8.2f s  %10.0f blocks/s\n", readTime, read / readTime);
  std::printf("read + simulate:     %8.2f s  %10.0f blocks/s  (840D model, summary only)\n", simulateTime,
              summary.blockCount / simulateTime);
  std::printf("simulate / read time ratio: %.2f\n", simulateTime / readTime);
  std::printf("simulated machining time %.1f s, length/feed %.1f s (x%.2f)\n", summary.totalTime, summary.naiveTime,
              summary.totalTime / summary.naiveTime);

  fiveAxis(blocks, summary, simulateTime);

  const MachineModel linuxcnc = loadMachine("linuxcnc-2.9", {HSM_MACHINES_DIR});
  SimulationSummary plain, looped;
  const double plainTime = seconds([&] {
    std::istringstream stream(program);
    plain = simulate(stream, linuxcnc).summary;
  });
  const std::string loops = loopProgram(blocks);
  long loopRead = 0;
  const double loopReadTime = seconds([&] {
    std::istringstream stream(loops);
    GcodeReader reader(stream);
    Block b;
    loopRead = 0;
    while (reader.next(b)) ++loopRead;
  });
  const double loopTime = seconds([&] {
    std::istringstream stream(loops);
    looped = simulate(stream, linuxcnc).summary;
  });
  std::printf("LinuxCNC model, plain program: %5.2f s  %10.0f blocks/s read + simulate\n", plainTime,
              plain.blockCount / plainTime);
  std::printf("LinuxCNC while loop (%ld blocks from a %zu-byte program): read only %5.2f s %10.0f blocks/s, "
              "read + simulate %5.2f s %10.0f blocks/s\n", loopRead, loops.size(), loopReadTime, loopRead / loopReadTime,
              loopTime, looped.blockCount / loopTime);

  const MachineModel fanuc = loadMachine("fanuc-31i-b5-vmc", {HSM_MACHINES_DIR});
  std::string fanucPlain = program;
  fanucPlain.replace(fanucPlain.find("CYCLE832(0.01,_ORI_FINISH,1)"), 28, "G05.1 Q1");
  SimulationSummary fanucSummary, macroSummary;
  const double fanucTime = seconds([&] {
    std::istringstream stream(fanucPlain);
    fanucSummary = simulate(stream, fanuc).summary;
  });
  const std::string macroLoop = macroLoopProgram(blocks);
  const double macroTime = seconds([&] {
    std::istringstream stream(macroLoop);
    macroSummary = simulate(stream, fanuc).summary;
  });
  std::printf("Fanuc model, plain program: %5.2f s  %10.0f blocks/s read + simulate\n", fanucTime,
              fanucSummary.blockCount / fanucTime);
  std::printf("Fanuc Macro B WHILE loop (%ld blocks): read + simulate %5.2f s %10.0f blocks/s\n", macroSummary.blockCount,
              macroTime, macroSummary.blockCount / macroTime);
  SimulationSummary siemensLoopSummary;
  const std::string siemensLoop = siemensLoopProgram(blocks);
  const double siemensLoopTime = seconds([&] {
    std::istringstream stream(siemensLoop);
    siemensLoopSummary = simulate(stream, machine).summary;
  });
  std::printf("840D WHILE loop (%ld blocks): read + simulate %5.2f s %10.0f blocks/s\n", siemensLoopSummary.blockCount,
              siemensLoopTime, siemensLoopSummary.blockCount / siemensLoopTime);
  {
    std::istringstream stream(finishingProgram(2000000));
    std::printf("heap in use while simulating 2000000 blocks on the Fanuc model (lines kept for jumps back): %.2f MB "
                "above the text\n", peakHeapMb(stream, fanuc));
  }

  {  // a subroutine defined at the top, then plain moves: only the subroutine's lines are kept
    std::istringstream stream("o<up> sub\nG0 Z5\no<up> endsub\n" + finishingProgram(2000000) + "o<up> call\n");
    std::printf("heap in use while simulating 2000000 blocks after a LinuxCNC subroutine: %.2f MB above the text\n",
                peakHeapMb(stream, linuxcnc));
  }
  for (long n : {1000000L, 4000000L}) {
    std::istringstream stream(finishingProgram(n));
    std::printf("heap in use while simulating %ld blocks: %.2f MB above the program text\n", n,
                peakHeapMb(stream, machine));
  }
  return 0;
}
