#!/usr/bin/env python3
"""One Python process for the many short Python calls of a test script (standard library only).

  python_server.py DIR
      Reads requests from the FIFO DIR/req and answers each on the FIFO DIR/resp, until a
      request "quit". test/cli/lib.sh starts it (python_server_start), sends the calls
      (run_py, which takes the arguments `python3` would) and stops it (python_server_stop);
      tools/test does so around every CLI script, so that the server's processor time is the
      script's.

Once it reads its requests it answers "ready". A request is NUL-separated fields: the client's process id, its working directory, the number
of its environment's entries and the entries (NAME=VALUE), then python3's arguments: `-`
(the script is the client's standard input), `-c CODE` or `FILE.py`, and the script's
arguments; a field "\\x01end" ends it. Each call runs as `python3 ARGS...` would, in fresh
globals: sys.argv, sys.path (the script's directory first), the working directory and the
environment are the client's (and so are the descriptors an argument /dev/stdin or /dev/fd/N
names), standard input is the client's (/proc/PID/fd/0), standard output
and error go to DIR/out and DIR/err (the client prints them), and the answer is its exit
status (1 and the traceback on stderr when it raised, SystemExit's code as python3 gives it).
Modules a call imports stay imported (that, and no interpreter to start, is the time saved);
the tools' checkers keep no state between calls.
"""
import io
import os
import re
import signal
import sys
import traceback

END = b"\x01end"


def requests(fd):
    """Each request's fields (bytes), read from the FIFO's descriptor fd."""
    buffer = b""
    while True:
        marker = buffer.find(b"\0" + END + b"\0")
        if marker >= 0:
            yield buffer[:marker].split(b"\0")
            buffer = buffer[marker + len(END) + 2:]
            continue
        chunk = os.read(fd, 65536)
        if not chunk:
            return
        buffer += chunk


def run(fields, directory, base_path, code_cache):
    """Runs one call; returns its exit status."""
    pid = fields[0].decode()
    os.chdir(os.fsdecode(fields[1]))
    n_env = int(fields[2])
    env = dict(os.fsdecode(e).split("=", 1) for e in fields[3:3 + n_env])
    os.environ.clear()
    os.environ.update(env)
    # the client's descriptors (/dev/stdin, a process substitution's /dev/fd/63) are its own
    args = [re.sub(r"^/dev/stdin$", "/dev/fd/0", os.fsdecode(a)) for a in fields[3 + n_env:]]
    args = [re.sub(r"^(/dev/fd|/proc/self/fd)/(?=[0-9]+$)", f"/proc/{pid}/fd/", a) for a in args]
    stdin_path = f"/proc/{pid}/fd/0"
    if args[0] == "-":
        with open(stdin_path, "rb") as script:
            source, name, argv = script.read(), "<stdin>", ["-"] + args[1:]
        path0 = ""
    elif args[0] == "-c":
        source, name, argv = args[1].encode(), "<string>", ["-c"] + args[2:]
        path0 = ""
    else:
        with open(args[0], "rb") as script:
            source, name, argv = script.read(), args[0], args
        path0 = os.path.dirname(os.path.abspath(args[0]))
    out = open(os.path.join(directory, "out"), "wb")
    err = open(os.path.join(directory, "err"), "wb")
    sys.stdout = io.TextIOWrapper(out, encoding="utf-8", write_through=True)
    sys.stderr = io.TextIOWrapper(err, encoding="utf-8", write_through=True)
    try:
        sys.stdin = open(stdin_path, encoding="utf-8") if args[0] != "-" else io.StringIO("")
    except OSError:
        sys.stdin = io.StringIO("")
    sys.argv = argv
    sys.path[:] = [path0] + base_path
    handlers = {number: signal.getsignal(number) for number in (signal.SIGPIPE, signal.SIGINT, signal.SIGTERM)}
    status = 0
    try:
        key = (name, source)
        code = code_cache.get(key)
        if code is None:
            code = code_cache[key] = compile(source, name, "exec")
        exec(code, {"__name__": "__main__", "__file__": name, "__builtins__": __builtins__})
    except SystemExit as stop:
        if stop.code is None:
            status = 0
        elif isinstance(stop.code, int):
            status = stop.code
        else:
            print(stop.code, file=sys.stderr)
            status = 1
    except BaseException:  # a call's crash is its failure, not the server's
        traceback.print_exc()
        status = 1
    finally:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        if sys.stdin is not None:
            sys.stdin.close()
        sys.stdout, sys.stderr, sys.stdin = sys.__stdout__, sys.__stderr__, sys.__stdin__
        for number, handler in handlers.items():  # a call's signal handlers are its own
            signal.signal(number, handler)
        out.close()
        err.close()
    return status & 0xFF


def main():
    directory = sys.argv[1]
    base_path = [p for p in sys.path[1:]]
    code_cache = {}
    fd = os.open(os.path.join(directory, "req"), os.O_RDWR)  # never at EOF while we run
    with open(os.path.join(directory, "resp"), "w", encoding="utf-8") as resp:
        resp.write("ready\n")
    for fields in requests(fd):
        if fields == [b"quit"]:
            break
        try:
            status = run(fields, directory, base_path, code_cache)
        except BaseException:  # a broken request: the call fails, the server goes on
            sys.stdout, sys.stderr = sys.__stdout__, sys.__stderr__
            with open(os.path.join(directory, "err"), "w", encoding="utf-8") as err:
                err.write(traceback.format_exc())
            open(os.path.join(directory, "out"), "wb").close()
            status = 1
        with open(os.path.join(directory, "resp"), "w", encoding="utf-8") as resp:
            resp.write(f"{status}\n")


if __name__ == "__main__":
    main()
