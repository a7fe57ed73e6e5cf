#!/bin/sh
# Usage: no_orphan_qemu.sh BUILD_DIR. Fails when a qemu-system-arm running firmware of this build
# (its -kernel under BUILD_DIR) has outlived the program that started it: its parent is no longer
# a program of BUILD_DIR (pxflow, or a test's own tool), so nothing will stop it. A QEMU that a
# running test's pxflow is using is not an orphan: tests that check every backend (the m4-qemu row
# included) may run beside this one. A suspect is looked at again 2 s later, so that a pxflow
# caught while it exits (its guardian then ends QEMU, hosts/core/guarded_child.cpp) is not one.
build=$1
[ -d "$build" ] || { echo "usage: no_orphan_qemu.sh BUILD_DIR" >&2; exit 2; }

# The pids of this build's QEMUs whose parent is not a program of the build.
suspects() {
  # The [m] keeps the pattern from matching a command line that contains it.
  for pid in $(pgrep -f "qemu-system-ar[m] .*-kernel $build/"); do
    ppid=$(ps -o ppid= -p "$pid" | tr -d ' ')
    [ -n "$ppid" ] || continue  # it ended meanwhile
    case "$(readlink "/proc/$ppid/exe" 2>/dev/null)" in
      "$build"/*) ;;  # its pxflow (or a test tool of this build) still runs it
      *) echo "$pid" ;;
    esac
  done
}

first=$(suspects)
[ -z "$first" ] && exit 0
sleep 2
status=0
for pid in $(suspects); do
  echo "$first" | grep -qx "$pid" || continue  # a new suspect: looked at by the next run
  ppid=$(ps -o ppid= -p "$pid" | tr -d ' ')
  echo "orphan QEMU: its parent (pid $ppid) is no program of $build; nothing will stop it:"
  ps -o pid=,args= -p "$pid"
  status=1
done
exit $status
