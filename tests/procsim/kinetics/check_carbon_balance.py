"""Runs `procsim kinetics run` and checks its carbon balance by value: the exit
status must be 0, and every run written (one, or one per member of a sweep)
must report a largest relative carbon imbalance below BOUND, in its
summary.csv and in every row of its timeseries.csv.

usage: check_carbon_balance.py BOUND OUT_DIR RUNS [--expect TEXT] PROCSIM ARG...
  OUT_DIR is emptied first and must be the command's -o; RUNS is the number
  of runs the command must write (1 without a sweep); TEXT must appear in
  what the command prints (e.g. the solver it used).

Why a round-off bound: the balance is a linear invariant of the species
equations (each reaction conserves carbon, the feed is constant).  expm is
exact for the linear system; RK4, like any Runge-Kutta method, and CVODE's BDF,
like any linear multistep method, preserve linear invariants exactly, and so
do Newton corrections with an exact Jacobian.  What is left is rounding: ~10
terms per step, a few thousand steps at most (rk4 at 10 s over 10 h), a
random walk of ~1e-13 and a linear worst case of ~4e-12, hence 1e-11.  A method that did
not conserve carbon would show at its error tolerance (cvode's rtol is 1e-9
in the shipped case).  Standard library only."""
import csv
import glob
import os
import shutil
import subprocess
import sys


def main(argv):
    bound, out, runs, command = float(argv[1]), argv[2], int(argv[3]), argv[4:]
    expect = None
    if command[:1] == ['--expect']:
        expect, command = command[1], command[2:]
    shutil.rmtree(out, ignore_errors=True)
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    sys.stdout.write(run.stdout)
    if run.returncode != 0:
        print('FAIL exit status %d' % run.returncode)
        return 1
    summaries = sorted(glob.glob(os.path.join(out, 'summary.csv')) + glob.glob(os.path.join(out, '*', 'summary.csv')))
    failed = []
    if expect is not None and expect not in run.stdout:
        failed.append('%r not in the output' % expect)
    if len(summaries) != runs:
        failed.append('%d runs written, expected %d' % (len(summaries), runs))
    for path in summaries:
        with open(path, newline='') as f:
            reported = [float(r['value']) for r in csv.DictReader(f) if r['quantity'] == 'carbon_balance_max_rel_error']
        with open(os.path.join(os.path.dirname(path), 'timeseries.csv'), newline='') as f:
            rows = [float(r['carbon_balance_rel_error']) for r in csv.DictReader(f)]
        if len(reported) != 1 or not rows:
            failed.append('%s: no carbon balance written' % path)
            continue
        worst = max(rows)
        ok = reported[0] < bound and worst < bound and abs(worst - reported[0]) <= 1e-6 * reported[0] + 1e-300
        print('%s %s: largest carbon imbalance %.3g (time series %.3g), bound %.0e'
              % ('ok  ' if ok else 'FAIL', os.path.relpath(path, out), reported[0], worst, bound))
        if not ok:
            failed.append(path)
    if failed:
        print('%d check(s) failed: %s' % (len(failed), '; '.join(failed)))
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
