#!/usr/bin/python3
# tests/bench/accuracy/cputime.py COMMAND...: runs COMMAND and prints, on
# standard error after its output, "cputime S": the user plus system CPU
# seconds the operating system charged to it and its threads (getrusage
# through wait4, microsecond figures). Exits with COMMAND's status.
# tests/bench/accuracy.sh times renders by CPU rather than wall clock so that
# other jobs on a shared machine disturb the figures less.
import os
import subprocess
import sys

child = subprocess.Popen(sys.argv[1:])
_, status, usage = os.wait4(child.pid, 0)
sys.stderr.write("cputime %.6f\n" % (usage.ru_utime + usage.ru_stime))
sys.exit(os.waitstatus_to_exitcode(status))
