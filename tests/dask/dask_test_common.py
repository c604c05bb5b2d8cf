"""What the Dask tests share: paths (the repository, its test data, the rcache under test from argv),
the driver module, and PASS/FAIL reporting with a failure list for the exit status."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import rcache_dask  # noqa: E402,F401  (the tests' driver and EXR reader)

RC = os.path.abspath(sys.argv[1])
DATA = os.path.join(ROOT, "tests", "cli", "data")
failures = []


def check(name, ok, detail=""):
    print(("PASS " if ok else "FAIL ") + name + (" (" + detail + ")" if detail else ""), flush=True)
    if not ok:
        failures.append(name)


def summary():
    """Prints the failure count; the exit status (0 when none failed)."""
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0
