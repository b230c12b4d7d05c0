"""Strict command-line arguments for the bench scripts (the same rules as the C++ tools).

    from cli_args import Parser, integer, seconds, text, path, thread_count, thread_list

Parser is argparse.ArgumentParser where an option that takes a value may be given once
(a second one is a usage error, not "the last one wins"). The types refuse, with exit
status 2 and a message naming the option:
  integer(lo, hi)  plain decimal digits only (no sign, space, "0x", "1e3", "1.5"), in [lo, hi]
  thread_count     integer(0, MAX_THREADS): the cap of `arrange --threads` and tritri.arrange,
                   read from arrangements/include/arrangements/thread_count.h (defined once)
  thread_list      comma-separated thread counts, none given twice (e.g. "1,2")
  seconds(lo, hi)  a plain decimal number of seconds (digits with an optional fraction; no
                   sign, exponent, NaN or infinity), in [lo, hi]
  text             a non-empty string
  path             a non-empty string, as a pathlib.Path
Scripts set sys.dont_write_bytecode before importing this module (no bench/__pycache__).
"""
import argparse
import math
import re
from pathlib import Path

_HEADER = Path(__file__).resolve().parent.parent / "arrangements" / "include" / "arrangements" / "thread_count.h"


def _max_threads():
    """The cap from the C++ header; without the header (a copied script) the tools decide."""
    try:
        m = re.search(r"#define ARRANGEMENTS_MAX_THREADS (\d+)", _HEADER.read_text())
    except OSError:
        m = None
    return int(m.group(1)) if m else 2**31 - 1


MAX_THREADS = _max_threads()


def _shown(value):
    return repr(value) if len(value) <= 40 else repr(value[:37] + "...")


def integer(lo, hi):
    def parse(value):
        if not re.fullmatch(r"[0-9]+", value) or not lo <= int(value) <= hi:
            raise argparse.ArgumentTypeError(f"expected an integer from {lo} to {hi}, got {_shown(value)}")
        return int(value)
    parse.__name__ = "integer"
    return parse


thread_count = integer(0, MAX_THREADS)


def thread_list(value):
    """Comma-separated thread counts, each a thread_count, none given twice."""
    counts = [thread_count(v) for v in value.split(",")]
    if len(set(counts)) != len(counts):
        raise argparse.ArgumentTypeError(f"a thread count given twice in {value!r}")
    return counts


def seconds(lo, hi):
    def parse(value):
        if not re.fullmatch(r"[0-9]+(\.[0-9]*)?|\.[0-9]+", value) or not lo <= float(value) <= hi:
            raise argparse.ArgumentTypeError(f"expected seconds from {lo:g} to {hi:g}, got {_shown(value)}")
        return float(value)
    parse.__name__ = "seconds"
    return parse


def positive_number(value):
    """A finite decimal number above 0 ("0.25", "1", "1e-3"), as arrange --round-max-move takes it."""
    if not re.fullmatch(r"([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][-+]?[0-9]+)?", value) or not 0 < float(value) < math.inf:
        raise argparse.ArgumentTypeError(f"expected a finite number above 0, got {_shown(value)}")
    return float(value)


def text(value):
    if value == "":
        raise argparse.ArgumentTypeError("expected a non-empty value, got ''")
    return value


def path(value):
    return Path(text(value))


class _Once(argparse.Action):
    """store, refusing a second occurrence of the option."""

    def __call__(self, parser, namespace, values, option_string=None):
        seen = namespace.__dict__.setdefault("_options_given", set())
        if self.dest in seen:
            parser.error(f"{'/'.join(self.option_strings)} given twice")
        seen.add(self.dest)
        setattr(namespace, self.dest, values)


class Parser(argparse.ArgumentParser):
    """argparse whose options with a value (action "store") may be given once."""

    def add_argument(self, *args, **kwargs):
        if args and args[0].startswith("-") and kwargs.get("action", "store") == "store":
            kwargs["action"] = _Once
        return super().add_argument(*args, **kwargs)

    def parse_args(self, args=None, namespace=None):
        ns = super().parse_args(args, namespace)
        ns.__dict__.pop("_options_given", None)
        return ns
