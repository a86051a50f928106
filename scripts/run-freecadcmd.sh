#!/usr/bin/env bash
# Runs a Python script in freecadcmd with arguments, without FreeCAD's start-up banner; keeps its exit code.
# Line by line (sed -u): a long script's progress shows as it is printed, not when sed's buffer fills.
set -o pipefail
freecadcmd "$@" 2>&1 | sed -u -E '/^  [ #]/d; /^(FreeCAD [0-9]+\.[0-9]+\.[0-9]+, Libs|FreeCAD 0\.|\(c\) Juergen|\(C\) 2001-|FreeCAD is free|FreeCAD wouldn.t)/d'
