"""What the program's Python tests share: named checks that count their failures,
and running the `silhouette` program."""

import subprocess

failures = []


def check(condition, message):
    """Prints the check's outcome; a failed one is remembered in `failures`."""
    print(("ok: " if condition else "FAILED: ") + message)
    if not condition:
        failures.append(message)


def run(program, *args):
    """Runs the program with `args`; returns its exit code, stdout and stderr."""
    done = subprocess.run([program, *args], capture_output=True, text=True, timeout=300)
    return done.returncode, done.stdout, done.stderr
