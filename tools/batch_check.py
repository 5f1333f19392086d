#!/usr/bin/env python3
"""Runs many calls of one of tools/' checkers in one Python process (standard library only).

  batch_check.py CHECKER JOBS OUTDIR
      CHECKER is a checker's module name in tools/ (plans_check, dxf_check): its main()
      reads sys.argv. JOBS has one call a line: a LABEL, then the call's arguments, separated
      by tabs. Each call runs as `python3 tools/CHECKER.py ARGS...` would: its standard output
      goes to OUTDIR/LABEL.out, and a line "LABEL<tab>STATUS" (its exit status; 1 when it
      raised) to standard output.

The test scripts note their calls and run them in one batch instead of starting Python per
deck (test/cli/lib.sh: check_job, check_batch).
"""
import contextlib
import importlib
import io
import os
import sys
import traceback


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(1)
    checker_name, jobs_path, out_dir = sys.argv[1:]
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    checker = importlib.import_module(checker_name)
    os.makedirs(out_dir, exist_ok=True)
    with open(jobs_path, encoding="utf-8") as jobs:
        for line in jobs:
            label, *args = line.rstrip("\n").split("\t")
            text = io.StringIO()
            status = 0
            sys.argv = [checker_name + ".py"] + args
            try:
                with contextlib.redirect_stdout(text):
                    checker.main()
            except SystemExit as stop:
                status = stop.code if isinstance(stop.code, int) else (0 if stop.code is None else 1)
            except Exception:  # a checker's crash is that call's failure, not the batch's
                text.write(traceback.format_exc())
                status = 1
            with open(os.path.join(out_dir, label + ".out"), "w", encoding="utf-8") as out:
                out.write(text.getvalue())
            print(f"{label}\t{status}")


if __name__ == "__main__":
    main()
