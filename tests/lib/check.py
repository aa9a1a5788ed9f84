"""check.py - the Python tests' one harness, the counterpart of check.sh
(the same lines, the same summary):
    check(ok, what)  count a check: print "  ok    WHAT" or "  FAIL  WHAT";
                     returns ok
    summary(name)    print the suite's last line, "NAME: N passed, M
                     failed" (what tests/run-all.py reads), and return the
                     exit status: 0 only when nothing failed
A script outside tests/ imports it by its own file's path:
    sys.path.insert(0, os.path.join(ROOT, "tests", "lib"))
"""
passed = 0
failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
        print("  ok    " + what)
    else:
        failed += 1
        print("  FAIL  " + what)
    return ok


def summary(name):
    print("%s: %d passed, %d failed" % (name, passed, failed))
    return 1 if failed else 0
