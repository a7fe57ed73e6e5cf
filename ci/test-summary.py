#!/usr/bin/env python3
"""One line for a CTest run, from its JUnit file (ctest --output-junit FILE):

    STAGE: P passed, F failed (names), S skipped (name: reason; ...), TIME

A skip's reason is the first line of the test's output that says SKIP (the missing-tool policy of
cmake/PxflowTests.cmake prints "SKIPPED: <reason>"), else its last line.

Usage: test-summary.py STAGE JUNIT_FILE TIME [REGISTERED WHY]
TIME is printed as given (e.g. "412 s (build 150 s, tests 262 s)"). REGISTERED, the number of
tests the build registered, and WHY, the reason some did not run, add "N left out (WHY)"."""
import sys
import xml.etree.ElementTree as ET


def skip_reason(case):
    text = case.findtext("system-out") or ""
    lines = [l.strip() for l in text.splitlines() if l.strip()]
    for line in lines:
        if "skip" in line.lower():
            return line
    return lines[-1] if lines else "no reason printed"


def main():
    if len(sys.argv) not in (4, 6):
        sys.stderr.write(__doc__)
        return 2
    stage, junit, time_text = sys.argv[1:4]
    registered, why = (int(sys.argv[4]), sys.argv[5]) if len(sys.argv) == 6 else (None, "")
    try:
        root = ET.parse(junit).getroot()
    except (OSError, ET.ParseError) as e:
        print(f"{stage}: no test results ({junit}: {e}), {time_text}")
        return 0
    passed, failed, skipped = [], [], []
    for case in root.iter("testcase"):
        name = case.get("name", "?")
        status = case.get("status", "")
        if status == "fail" or case.find("failure") is not None:
            failed.append(name)
        elif status in ("notrun", "disabled") or case.find("skipped") is not None:
            skipped.append(f"{name}: {skip_reason(case)}")
        else:
            passed.append(name)
    parts = [f"{len(passed)} passed", f"{len(failed)} failed"]
    if failed:
        parts[-1] += " (" + "; ".join(failed) + ")"
    parts.append(f"{len(skipped)} skipped" + (" (" + "; ".join(skipped) + ")" if skipped else ""))
    ran = len(passed) + len(failed) + len(skipped)
    if registered is not None and registered > ran:
        parts.append(f"{registered - ran} left out ({why})")
    print(f"{stage}: " + ", ".join(parts) + f", {time_text}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
