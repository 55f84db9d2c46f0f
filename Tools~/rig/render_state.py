#!/usr/bin/env python3
"""The render state of a ShaderLab pass, as gt-harness options (Tools~/harness/README.md).

    render_state.py [--shader FILE] [--draw tessellated|fallback] [--lightmode NAME]...

Prints one line, e.g. "--cull back --ztest lequal --zwrite on --zclip on --color-mask rgba": the
Cull, ZTest, ZWrite, ZClip and ColorMask of the pass the rig's own variants stand for. By default
that is the forward colour pass of Shaders/GregoryTerrain.shader (UniversalForwardOnly, ForwardOnly,
ForwardBase) in the SubShaders of the draw (the "GregoryTerrainDraw" tag: Tessellated or Fallback);
every such pass must have the same state, or it fails naming the two that differ. A command a pass
does not name takes the SubShader's, else ShaderLab's default (Cull Back, ZTest LEqual, ZWrite On,
ZClip True, ColorMask RGBA). A value read from a material property ("Cull [_Cull]") has no value
here: it fails naming the pass and the command. Exit 0, or 2 with one "render_state: ..." line.

The pass's Stencil block (stencil_options) is read apart: the rig's standalone target has no stencil,
so this line leaves it out; pipeline_pass.py gives it to the harness as --stencil for the pass it draws.

The SubShader and Pass blocks come from shaderlab.py's parser (parse_shader).
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shaderlab  # noqa: E402

FORWARD_LIGHTMODES = ("UniversalForwardOnly", "ForwardOnly", "ForwardBase")
DRAW_TAG = "GregoryTerrainDraw"
# ShaderLab command -> (harness option, ShaderLab's default, accepted values in lower case).
COMMANDS = {
    "Cull": ("--cull", "back", {"back", "front", "off"}),
    "ZTest": ("--ztest", "lequal", {"less", "lequal", "equal", "gequal", "greater", "notequal", "always", "never"}),
    "ZWrite": ("--zwrite", "on", {"on", "off"}),
    "ZClip": ("--zclip", "on", {"on", "off", "true", "false"}),
    "ColorMask": ("--color-mask", "rgba", None),
}
COLOR_MASK = re.compile(r"^(0|r?g?b?a?)$")
# A property a command reads ("ZClip [_ZClip]") that the drawing pipeline sets globally (CommandBuffer.SetGlobalFloat),
# as a ShaderLab value: a caller that draws such a pass sets it here (pipeline_pass_hdrp.py: HDRP's _ZClip).
GLOBAL_PROPERTIES = {}


# ShaderLab's Stencil commands (lower case) -> the words they take; Ref and the masks take 0..255.
STENCIL_COMPARE = {"never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always"}
STENCIL_OPS = {"keep", "zero", "replace", "incrsat", "decrsat", "invert", "incrwrap", "decrwrap"}
STENCIL_COMMANDS = {"ref": None, "readmask": None, "writemask": None,
                    **{stem + face: (STENCIL_COMPARE if stem == "comp" else STENCIL_OPS)
                       for stem in ("comp", "pass", "fail", "zfail") for face in ("", "front", "back")}}


class RenderStateError(Exception):
    pass


def tags(text):
    """{name: value} of the first Tags block in text (a pass's or SubShader's own part)."""
    m = re.search(r"\bTags\s*\{([^}]*)\}", text)
    return dict(re.findall(r'"(\w+)"\s*=\s*"([^"]*)"', m.group(1))) if m else {}


def commands(text, where):
    """The render-state commands written directly in text (nested blocks such as Tags or Stencil
    and quoted strings left out), values in lower case. ShaderLab is free-form: a command is its
    keyword and the next word, wherever the line breaks."""
    flat = re.sub(r'"[^"]*"', " ", re.sub(r"\{[^{}]*\}", " ", text))
    words = flat.split()
    out = {}
    for i, word in enumerate(words[:-1]):
        if word not in COMMANDS:
            continue
        value = words[i + 1]
        if value.startswith("[") and value[1:-1] in GLOBAL_PROPERTIES:
            value = GLOBAL_PROPERTIES[value[1:-1]]
        if value.startswith("["):
            raise RenderStateError(f"{where}: {word} {value} reads a material property, which has no value here")
        accepted = COMMANDS[word][2]
        low = value.lower()
        if (accepted is not None and low not in accepted) or (accepted is None and not COLOR_MASK.match(low)):
            raise RenderStateError(f"{where}: {word} '{value}' is not a value ShaderLab takes")
        out[word] = {"true": "on", "false": "off"}.get(low, low)
    return out


def stencil_block(text, where):
    """The body of the Stencil block written directly in text (a pass's or SubShader's own part), its
    commands checked and [_Property] values filled from GLOBAL_PROPERTIES, as one line; None without one."""
    m = re.search(r"\bStencil\s*\{([^{}]*)\}", re.sub(r'"[^"]*"', " ", text))
    if not m:
        return None
    words = m.group(1).split()
    if not words or len(words) % 2:
        raise RenderStateError(f"{where}: Stencil {{{m.group(1).strip()}}} is not command-value pairs")
    out, seen = [], set()
    for command, value in zip(words[::2], words[1::2]):
        key = command.lower()
        if key not in STENCIL_COMMANDS:
            raise RenderStateError(f"{where}: Stencil command '{command}' is not one ShaderLab takes")
        if key in seen:
            raise RenderStateError(f"{where}: Stencil {command} is given twice")
        seen.add(key)
        if value.startswith("[") and value[1:-1] in GLOBAL_PROPERTIES:
            value = GLOBAL_PROPERTIES[value[1:-1]]
        if value.startswith("["):
            raise RenderStateError(f"{where}: Stencil {command} {value} reads a material property, which has no value here")
        words_taken = STENCIL_COMMANDS[key]
        ok = value.isdigit() and int(value) <= 255 if words_taken is None else value.lower() in words_taken
        if not ok:
            raise RenderStateError(f"{where}: Stencil {command} '{value}' is not a value ShaderLab takes")
        out.append(f"{command} {value}")
    return " ".join(out)


def stencil_options(sub, p, where):
    """["--stencil", body] for the pass's Stencil block (else the SubShader's), or [] where neither has
    one: Unity's default, the stencil test off."""
    body = stencil_block(p.shaderlab, where)
    if body is None:
        body = stencil_block(re.sub(r"\bPass\s*\{.*", "", sub.outer, flags=re.S), f"{where} (SubShader)")
    return [] if body is None else ["--stencil", body]


def pass_state(sub, p, where):
    state = {name: default for name, (_, default, _) in COMMANDS.items()}
    state.update(commands(sub.outer, f"{where} (SubShader)"))
    state.update(commands(p.shaderlab, where))
    return state


def forward_passes(subs, draw, lightmodes):
    """(where, state) of every pass of the draw's SubShaders whose LightMode is one of lightmodes."""
    found = []
    for sub in subs:
        if tags(sub.outer).get(DRAW_TAG, "").lower() != draw:
            continue
        for p in sub.passes:
            if tags(p.shaderlab).get("LightMode") in lightmodes:
                where = f"SubShader {sub.index} ({sub.pipeline}) Pass \"{p.name}\""
                found.append((where, pass_state(sub, p, where)))
    return found


def harness_options(shader, draw, lightmodes=FORWARD_LIGHTMODES):
    """The one state all the matching passes share, as harness options."""
    found = forward_passes(shaderlab.parse_shader(shader), draw, lightmodes)
    if not found:
        raise RenderStateError(f"{shader}: no pass with LightMode {', '.join(lightmodes)} in a SubShader "
                               f"tagged \"{DRAW_TAG}\" = \"{draw}\"")
    first_where, first = found[0]
    for where, state in found[1:]:
        for name in COMMANDS:
            if state[name] != first[name]:
                raise RenderStateError(f"{where} has {name} {state[name]} but {first_where} has {name} {first[name]}: "
                                       "the rig's variants stand for one state")
    return " ".join(f"{COMMANDS[name][0]} {first[name]}" for name in COMMANDS)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--shader", default=os.path.join(shaderlab.DEFAULT_PKG, "Shaders", "GregoryTerrain.shader"))
    ap.add_argument("--draw", choices=["tessellated", "fallback"], default="tessellated")
    ap.add_argument("--lightmode", action="append", help="a pass's LightMode tag (repeatable; default the forward colour passes)")
    a = ap.parse_args(argv)
    try:
        print(harness_options(a.shader, a.draw, tuple(a.lightmode) if a.lightmode else FORWARD_LIGHTMODES))
    except (RenderStateError, OSError, ValueError) as e:
        print(f"render_state: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
