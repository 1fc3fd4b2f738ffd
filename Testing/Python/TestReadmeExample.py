"""Runs the README's Python example (the first ```python block of README.md)
and checks what it prints: the closed-form optical depth of the cosine noise
along the ray agrees with the marched one to 1e-8 relative, is positive, and
the transmittance is exp(-depth), neither 0 nor 1 (a newcomer must see the
closed form at work, not "1.0").

    TestReadmeExample.py README.md
"""

import contextlib
import io
import math
import re
import sys


def example(readme):
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    match = re.search(r"^```python\n(.*?)^```$", text, re.M | re.S)
    if not match:
        raise SystemExit("FAIL: no ```python block in " + readme)
    return match.group(1)


def main():
    code = example(sys.argv[1])
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(code, "README.md example", "exec"), {"__name__": "__readme__"})
    printed = out.getvalue()
    print(printed, end="")
    depth = re.search(r"optical depth: ([0-9.eE+-]+) in closed form, ([0-9.eE+-]+) marched",
                      printed)
    transmittance = re.search(r"transmittance: ([0-9.]+)", printed)
    failures = []
    if not depth or not transmittance:
        failures.append("the example does not print the optical depths and the transmittance")
    else:
        closed, marched = float(depth.group(1)), float(depth.group(2))
        t = float(transmittance.group(1))
        if not closed > 0.0:
            failures.append("the closed-form optical depth %g is not positive" % closed)
        if abs(closed - marched) > 1e-8 * max(closed, 1e-300):
            failures.append("closed form %.12g and march %.12g differ" % (closed, marched))
        if abs(t - math.exp(-closed)) > 5e-5:
            failures.append("transmittance %g is not exp(-%g)" % (t, closed))
        if not 0.05 < t < 0.95:
            failures.append("transmittance %g shows no medium at work" % t)
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


sys.exit(main())
