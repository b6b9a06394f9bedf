#!/usr/bin/env python3
"""test_times.py JUNIT [N] — the N (default 10) slowest tests of a ctest run, from the JUnit
file that `ctest --output-junit` wrote: seconds, name and label-free status, slowest first,
then the tests' summed time (over all jobs, so more than the run's wall time with -j2).

test_times.py JUNIT --costs — "name seconds" for every test of a second or more, slowest first:
the contents of ci/test_costs.txt, from which ci/test.sh tells ctest to start the longest tests
first in a fresh build folder. Names with spaces (a parameter's path) are left out."""
import sys
import xml.etree.ElementTree as ElementTree


def main() -> int:
    if len(sys.argv) < 2:
        print("usage: test_times.py JUNIT [N]", file=sys.stderr)
        return 2
    costs = len(sys.argv) > 2 and sys.argv[2] == "--costs"
    count = int(sys.argv[2]) if len(sys.argv) > 2 and not costs else 10
    try:
        cases = ElementTree.parse(sys.argv[1]).getroot().iter("testcase")
    except (OSError, ElementTree.ParseError) as error:
        print(f"test_times: {sys.argv[1]}: {error}", file=sys.stderr)
        return 1
    timed = []
    for case in cases:
        status = case.get("status", "run")
        if case.find("failure") is not None:
            status = "failed"
        elif case.find("skipped") is not None:
            status = "skipped"
        timed.append((float(case.get("time", "0")), case.get("name", "?"), status))
    timed.sort(reverse=True)
    if costs:
        for seconds, name, _ in timed:
            if seconds >= 1.0 and " " not in name:
                print(f"{name} {seconds:.1f}")
        return 0
    print(f"the {min(count, len(timed))} slowest of {len(timed)} tests:")
    for seconds, name, status in timed[:count]:
        suffix = "" if status in ("run", "passed") else f" ({status})"
        print(f"  {seconds:8.2f} s  {name}{suffix}")
    print(f"  {sum(t[0] for t in timed):8.1f} s  of test time in all (summed over jobs)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
