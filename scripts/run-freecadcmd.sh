#!/usr/bin/env bash
# Runs a Python script in freecadcmd with arguments, without FreeCAD's start-up banner; keeps its exit code.
set -o pipefail
freecadcmd "$@" 2>&1 | sed -E '/^  [ #]/d; /^(FreeCAD 0\.|\(c\) Juergen|FreeCAD is free|FreeCAD wouldn.t)/d'
