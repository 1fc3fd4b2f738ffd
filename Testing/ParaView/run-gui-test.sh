#!/bin/sh
# Runs TestParaViewGUI.py in ParaView's GUI and turns the verdict it writes
# into an exit code (0 passed and the GUI exited cleanly, 125 skipped, 1
# otherwise): the GUI's own exit code does not say whether its script failed.
#   run-gui-test.sh PARAVIEW PLUGIN OUTPUT_FOLDER
set -u
paraview="$1"
export TYNDALL_PARAVIEW_PLUGIN="$2"
mkdir -p "$3"
export TYNDALL_PARAVIEW_GUI_RESULT="$3/gui-result.txt"
rm -f "$TYNDALL_PARAVIEW_GUI_RESULT"
here="$(cd "$(dirname "$0")" && pwd)"
export TYNDALL_PARAVIEW_TEST_DIR="$here"
"$paraview" "--script=$here/TestParaViewGUI.py" --exit
status=$?
if [ ! -f "$TYNDALL_PARAVIEW_GUI_RESULT" ]; then
  echo "the GUI (exit code $status) wrote no verdict" >&2
  exit 1
fi
cat "$TYNDALL_PARAVIEW_GUI_RESULT"
case "$(cat "$TYNDALL_PARAVIEW_GUI_RESULT")" in
  passed*)
    # A crash while the GUI closes fails the test too.
    if [ "$status" -ne 0 ]; then
      echo "the GUI exited with code $status after its script passed" >&2
      exit 1
    fi
    exit 0 ;;
  skipped*) exit 125 ;;
  *) exit 1 ;;
esac
