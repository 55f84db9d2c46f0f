#!/usr/bin/env python3
"""The range check of the rig's numeric options, for its python scripts (argparse type=) and its
bash scripts (check_number in common.sh; the carried device scripts call this file beside them);
python scripts declare theirs with add_number.
gt-cli's own options are checked in Tools~/dotnet/Gt/Args.cs with the same messages:
    gt CMD: --tiles 0 is out of range (1..64)          (exit 2)

    python3 options.py CMD OPTION FORM [VALUE]
FORM: a range name of RANGES; NAME,... for a list of them (comma- or space-separated); size for
WIDTHxHEIGHT in pixels. VALUE left out: "needs a value". Prints nothing and exits 0 when VALUE holds.
"""
import math
import re
import sys

# name: (whole, lowest, highest, lowest excluded)
RANGES = {
    "frames": (True, 1, 100000, False),      # 100,000 frames of 1080p: minutes on a GPU, hours on lavapipe
    "rounds": (True, 1, 1000, False),
    "pixels": (True, 1, 16384, False),       # Vulkan's and D3D11's largest framebuffer side
    "tiles": (True, 1, 1024, False),         # gt-cli pack --tiles (TessellationSettings.Validate)
    "factor": (False, 0, 64, False),         # gt-cli pack --factor: 0 adaptive, else uniform up to the hardware's 64
    "jobs": (True, 1, 256, False),
    "patches": (True, 1, 1024, False),       # a side of a fitted grid, as gt-cli fit-bench --patches
    "samples": (True, 2, 16384, False),      # a side of a heightmap, as gt-cli fit-bench --size
    "metres": (False, 0, 1e8, True),         # a terrain's width, as gt-cli lod-scene --terrain-m
    "resolution": (True, 64, 4096, False),   # a snow map's side (SnowSettings), as gt-cli snow-scene --resolutions
    "seconds": (False, 0, 3600, True),
    "elevation": (False, -90, 90, False),    # a light's degrees above the horizon
    "azimuth": (False, -360, 360, False),    # a light's compass degrees
    "ulps": (True, -8, 8, False),            # float32 steps a broken-input option nudges a depth by
}
MAX_LIST = 64  # as gt-cli's NumericOption.MaxListCount


class OptionError(ValueError):
    """A bad value; the message names the value and the range (the caller adds the option)."""


def _n(v):
    return str(int(v)) if float(v).is_integer() and abs(v) < 1e15 else repr(float(v))


def range_text(name):
    whole, lo, hi, open_lo = RANGES[name]
    return (">" if open_lo else "") + _n(lo) + ".." + _n(hi)


def parse(name, text):
    """The number in text if it lies in RANGES[name], else OptionError."""
    whole, lo, hi, open_lo = RANGES[name]
    r = range_text(name)
    if text is None or text == "":
        raise OptionError(f"needs a value ({r})")
    try:
        v = float(text)
    except ValueError:
        raise OptionError(f"{text} is not a number ({r})") from None
    if not math.isfinite(v):
        raise OptionError(f"{text} is not a finite number ({r})")
    if not ((v > lo) if open_lo else (v >= lo)) or v > hi:
        raise OptionError(f"{text} is out of range ({r})")
    if whole and not re.fullmatch(r"[+-]?[0-9]+", text.strip()):
        raise OptionError(f"{text} is not an integer ({r})")
    return int(v) if whole else v


def parse_form(form, text):
    """FORM as the command line gives it: NAME, NAME,... (a list) or size (WIDTHxHEIGHT)."""
    if form == "size":
        if not text:
            raise OptionError(f"needs a value: WIDTHxHEIGHT ({range_text('pixels')} each)")
        parts = text.split("x")
        if len(parts) != 2:
            raise OptionError(f"{text} is not WIDTHxHEIGHT ({range_text('pixels')} each)")
        return [parse("pixels", p) for p in parts]
    if form.endswith(",..."):
        name = form[:-4]
        items = [t for t in re.split(r"[,\s]+", (text or "").strip()) if t]
        if not items:
            raise OptionError(f"needs a value: one or more numbers ({range_text(name)})")
        if len(items) > MAX_LIST:
            raise OptionError(f"has {len(items)} numbers (at most {MAX_LIST})")
        return [parse(name, t) for t in items]
    return parse(form, text)


def add_number(parser, *flags, range, **kwargs):
    """parser.add_argument for a numeric option in RANGES[range]: a bad or missing value ends the
    script with argparse's "error: argument --jobs: 0 is out of range (1..256)", exit 2."""
    import argparse

    def check(text):
        try:
            return parse(range, text)
        except OptionError as e:
            raise argparse.ArgumentTypeError(str(e)) from None
    check.__name__ = range

    class NeedsValue(argparse.Action):
        def __call__(self, p, namespace, value, option_string=None):
            if value is None:
                p.error(f"argument {option_string}: needs a value ({range_text(range)})")
            setattr(namespace, self.dest, value)
    return parser.add_argument(*flags, type=check, nargs="?", action=NeedsValue, **kwargs)


def main(argv):
    if len(argv) not in (3, 4):
        print("usage: options.py CMD OPTION FORM [VALUE]", file=sys.stderr)
        return 2
    cmd, option, form = argv[:3]
    text = argv[3] if len(argv) == 4 else None
    try:
        parse_form(form, text)
    except OptionError as e:
        whole = "" if form in RANGES or not text else f" {text}:"
        print(f"gt {cmd}: {option}{whole} {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
