#!/usr/bin/env python3
"""Runs tests/freecad/post_test.py under freecadcmd (which exits 0 whatever
the script does) and fails unless the script wrote "ok".  usage: run_post_test.py ACODRILL"""
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
with tempfile.TemporaryDirectory() as work:
    result = os.path.join(work, "result.txt")
    env = dict(os.environ, ACODRILL=sys.argv[1], RESULT=result, POST_TEST_SCRIPT=os.path.join(here, "post_test.py"), HOME=work)
    run = subprocess.run(["freecadcmd", os.path.join(here, "post_test.py")], env=env, capture_output=True, text=True, timeout=600)
    verdict = open(result).read() if os.path.exists(result) else "no verdict written\n" + run.stdout[-2000:] + run.stderr[-2000:]
print(verdict, end="")
sys.exit(0 if verdict.startswith("ok") else 1)
