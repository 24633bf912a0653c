# acodrill as a FreeCAD CAM (Path) post-processor (issue 83).
#
# It posts the Job with the FreeCAD post you name, exactly as FreeCAD would,
# then reorders the drilling with `acodrill plan --keep-style --keep-milling`:
# every drilling operation's holes in the order an ant colony finds shortest,
# each with its own cycle, depth, pecks and dwell; every other line as posted,
# a profile's or pocket's milling too (the drilling is reordered between them,
# never across one).
#
# Install: copy this file into FreeCAD's macro folder (Macro > Macros...
# shows it; or Preferences > Path > Job > "Post processor" search path),
# then in the Job's Output tab choose the post processor "acodrill" and give
# its arguments, e.g.
#     --post linuxcnc
#     --post grbl -- --iterations 3000 --time-limit 10
# Arguments: --post NAME (FreeCAD's post to post with first: linuxcnc,
# mach3_mach4, grbl, marlin, smoothie, uccnc, centroid, fanuc, ...; default
# linuxcnc), --post-args "..." (that post's own arguments), --acodrill PATH
# (the program; default: acodrill on PATH), and after "--" acodrill plan's
# own options. FreeCAD 0.20 (Path workbench) and 1.0 (CAM workbench, whose
# posts moved to Path.Post.scripts) are both handled.
import importlib
import os
import shlex
import shutil
import subprocess
import tempfile

TOOLTIP = """acodrill: posts with another FreeCAD post (--post NAME), then
reorders its drilling with acodrill plan --keep-style (shortest travel,
same holes, cycles, depths and tools)."""

TOOLTIP_ARGS = """
--post NAME         FreeCAD's post to post with first (default linuxcnc)
--post-args "..."   that post's own arguments
--acodrill PATH     the acodrill program (default: acodrill on PATH)
-- OPTIONS          acodrill plan's options, e.g. -- --iterations 3000
"""


def _post_module(name):
    """FreeCAD's own post NAME: 0.20's PathScripts.post, 1.0's Path.Post.scripts, or one on the search path."""
    for module in ("PathScripts.post.%s_post" % name, "Path.Post.scripts.%s_post" % name, "%s_post" % name):
        try:
            return importlib.reload(importlib.import_module(module))
        except ImportError:
            continue
    raise RuntimeError("acodrill_post: no FreeCAD post named %r" % name)


def _arguments(argstring):
    words = shlex.split(argstring or "")
    post, post_args, program, plan_args = "linuxcnc", "", shutil.which("acodrill") or "acodrill", []
    i = 0
    while i < len(words):
        w = words[i]
        if w == "--":
            plan_args = words[i + 1:]
            break
        if w in ("--post", "--post-args", "--acodrill") and i + 1 < len(words):
            value = words[i + 1]
            if w == "--post":
                post = value
            elif w == "--post-args":
                post_args = value
            else:
                program = value
            i += 2
            continue
        raise RuntimeError("acodrill_post: unknown argument %r (see its TOOLTIP_ARGS)" % w)
    return post, post_args, program, plan_args


def export(objectslist, filename, argstring):
    post, post_args, program, plan_args = _arguments(argstring)
    module = _post_module(post)
    with tempfile.TemporaryDirectory(prefix="acodrill-post-") as work:
        posted = os.path.join(work, "posted.nc")
        args = (post_args + " --no-show-editor").strip()
        try:
            text = module.export(objectslist, posted, args)
        except SystemExit:  # a post that takes no --no-show-editor
            module = _post_module(post)
            text = module.export(objectslist, posted, post_args)
        if (not os.path.exists(posted) or os.path.getsize(posted) == 0) and text:
            with open(posted, "w") as f:
                f.write(text)
        reordered = os.path.join(work, "reordered.nc")
        run = subprocess.run([program, "plan", posted, "-o", reordered, "--keep-style", "--keep-milling", "-q"] + plan_args,
                             capture_output=True, text=True)
        if run.returncode != 0:
            # acodrill's one line, which names what it could not take; FreeCAD shows it.
            raise RuntimeError(run.stderr.strip().replace(posted, "the %s post's program" % post))
        with open(reordered) as f:
            gcode = f.read()
    if filename and filename != "-":
        with open(filename, "w") as f:
            f.write(gcode)
    return gcode
