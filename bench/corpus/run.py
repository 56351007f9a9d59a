#!/usr/bin/env python3
# bench/corpus/run.py — runs every fabvdb command on the corpus meshes with one
# fixed recipe, under a time and memory cap per run, checks every output with
# the independent checker (corpus_check, built from bench/corpus/corpus_check.cpp)
# and writes one table, model x command, as Markdown and JSON.
# GPL-3.0-or-later. Recipe, selection rules and verdicts: bench/corpus/README.md.
#
#   python3 bench/corpus/run.py --fabvdb build/fabvdb --checker build/bench/corpus_check \
#       --out corpus-out [--subset all|smallest20] [--jobs 2] [--time-cap 120] [--mem-cap 8G]
#
# Exits 0 when no run FAILs, 1 otherwise. Each model's record is kept in
# OUT/runs/MODEL/record.json; the table is assembled from every record found,
# so `--only MODEL` reruns one model and refreshes its row, and `--resume`
# keeps each model whose record came from the same binaries and recipe.
import argparse
import concurrent.futures
import datetime
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import time

WALL_MM = 2.0
COMMANDS = ["info", "check", "repair", "hollow", "drain", "powder-sim", "decompose", "mold"]
MOLD_SHARE = {"cad": 12, "sculpture": 10, "scan": 6, "dirty": 7, "large": 3, "degenerate": 2}
WALL_TOLERANCE = 0.9          # measured wall >= 90% of --wall
MOLD_MAX_RATIO = 0.01         # input within 1% of the diagonal of the cast parts (max)
MOLD_MEAN_RATIO = 0.001       # and 0.1% (area-weighted mean)
KEPT_TOLERANCE = 1e-5         # x diagonal: a clean input "kept" by repair (float rounding only)
FIDELITY_FAR_RATIO = 0.01     # every solid written: input surface farther than 1% of the diagonal
FIDELITY_FAR_VOXELS = 3.0      # (or 3 of the command's voxels, if more) is far; at most
FIDELITY_FAR_SHARE = 0.02      # 2% of it may be, and the area-weighted mean at most
FIDELITY_MEAN_RATIO = 0.001    # 0.1% of the diagonal (or 0.5 voxel, if more: drain's wall / 4
FIDELITY_MEAN_VOXELS = 0.5     # is 0.5 mm, 0.6% of a 60 mm cube's diagonal)
CHECK_PROCESS = "sla"
CHECK_NAMES = ["mesh", "units", "wall_thickness", "small_features", "holes", "trapped_volumes", "overhangs", "cups"]
CHECK_STATUSES = ["pass", "warn", "fail"]
CHECK_FAIL_EXIT = 5           # `fabvdb check`: the verdict reached --fail-on (fail, by default)
SIZE_TOLERANCE = 1e-6         # x the fitted size: the report's box against --fit and the checker's diagonal
VOLUME_TOLERANCE = 1e-5       # x the volume: a clean input's mesh volume (the checker's is after float rounding)


def read_manifest(corpus):
    rows = []
    with open(os.path.join(corpus, "manifest.tsv")) as f:
        header = f.readline().rstrip("\n").split("\t")
        for line in f:
            if line.strip():
                row = dict(zip(header, line.rstrip("\n").split("\t")))
                row["triangles"] = int(row["triangles"])
                rows.append(row)
    return rows


def smallest(rows, count):
    return sorted(rows, key=lambda r: (r["triangles"], r["file"]))[:count]


def mold_selection(rows):
    """Per category, MOLD_SHARE[c] meshes spread evenly over its triangle-count order."""
    chosen = set()
    for category, share in MOLD_SHARE.items():
        members = sorted((r for r in rows if r["category"] == category), key=lambda r: (r["triangles"], r["file"]))
        n = len(members)
        for i in range(min(share, n)):
            chosen.add(members[(i * n) // share if share <= n else i]["file"])
    return chosen


class Runner:
    def __init__(self, args):
        self.args = args

    def run(self, argv, workdir, name):
        """Runs one command under the caps; returns exit, seconds, peak MiB, stderr."""
        timefile = os.path.join(workdir, name + ".time")
        cmd = ["timeout", "-k", "5", str(self.args.time_cap), "/usr/bin/time", "-f", "%M", "-o", timefile,
               "prlimit", "--as=" + str(self.args.mem_cap_bytes), "--"] + argv
        start = time.monotonic()
        p = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           errors="replace")
        seconds = time.monotonic() - start
        peak = None
        try:
            with open(timefile) as f:
                values = [l for l in f.read().split() if l.isdigit()]
                peak = int(values[-1]) / 1024.0 if values else None
        except OSError:
            pass
        stderr = p.stderr
        # GNU time reports a signal as "Command terminated by signal N" in its file.
        try:
            with open(timefile) as f:
                m = re.search(r"terminated by signal (\d+)", f.read())
                if m:
                    stderr += "\n[killed by signal %s]" % m.group(1)
                    if p.returncode == 0:
                        p.returncode = 128 + int(m.group(1))
        except OSError:
            pass
        return {"exit": p.returncode, "seconds": round(seconds, 2),
                "timed_out": p.returncode in (124, 137) and seconds >= self.args.time_cap, "peak_mib": None if peak is None else round(peak),
                "stderr": stderr.strip()[-2000:], "command": " ".join(argv)}

    def check(self, argv):
        p = subprocess.run(["timeout", str(self.args.check_cap), self.args.checker] + argv, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True, errors="replace")
        try:
            out = json.loads(p.stdout.strip().splitlines()[-1])
        except (ValueError, IndexError):
            out = {"error": "checker exit %d: %s" % (p.returncode, p.stderr.strip()[-500:])}
        if p.returncode == 124:
            out = {"error": "checker timed out after %d s" % self.args.check_cap}
        if p.returncode != 0 and "error" not in out:
            out["error"] = "checker exit %d: %s" % (p.returncode, p.stderr.strip()[-800:])
        return out


def left_files(path):
    folder, base = os.path.split(path)
    if not os.path.isdir(folder):
        return []
    return [f for f in os.listdir(folder) if f == base or f.startswith(base + ".partial")]


def judge_failure(run, input_path, output, input_facts, closed_input):
    """Verdict of a non-zero exit: refused (clear message, no output) or FAIL."""
    code, err = run["exit"], run["stderr"]
    name = os.path.basename(input_path)
    if run.get("timed_out"):
        return "FAIL", "no result within the time cap (%.0f s)" % run["seconds"]
    if code >= 128 or code < 0:
        return "FAIL", "crashed (%s)" % (err.splitlines()[-1] if err else "exit %d" % code)
    if output and left_files(output):
        return "FAIL", "exit %d left an output file behind" % code
    if code in (2, 3) and name in err:
        if code == 2 and input_facts.get("valid") and not encloses_nothing(input_facts):
            return "FAIL", "refused a clean closed solid: " + first_line(err)
        if code == 2 and closed_input and not encloses_nothing(input_facts):
            return "FAIL", "refused a closed input: " + first_line(err)
        return "refused", first_line(err)
    if code in (2, 3):
        return "FAIL", "exit %d without naming the file: %s" % (code, first_line(err))
    return "FAIL", "exit %d: %s" % (code, first_line(err))


def encloses_nothing(facts):
    """A flat sliver: closed, yet it encloses no volume to keep. The checker
    cannot tell inside from outside of some shell of the input, or the
    input's mean thickness (2 volume / area) is under 1e-4 of its diagonal,
    thinner than any printer's resolution at the recipe's 60 mm."""
    if any("undecided orientation" in d for d in facts.get("defects", [])):
        return True
    thickness, diagonal = facts.get("mean_thickness"), facts.get("diagonal")
    return thickness is not None and diagonal is not None and thickness < 1e-4 * diagonal


def threemf_repeated_corner_triangles(path):
    """Triangles of a 3MF file whose corners repeat a vertex index, counted in
    its XML: the 3MF core specification forbids them and lib3mf drops them as
    it reads, so fabvdb never sees them."""
    import zipfile
    count = 0
    with zipfile.ZipFile(path) as archive:
        for name in archive.namelist():
            if name.endswith(".model"):
                text = archive.read(name).decode("utf-8", "replace")
                for a, b, c in re.findall(r'<triangle\s+v1="(\d+)"\s+v2="(\d+)"\s+v3="(\d+)"', text):
                    count += a == b or b == c or a == c
    return count


def first_line(text):
    for line in text.splitlines():
        if line.startswith("fabvdb"):
            return line.strip()[:300]
    return text.strip().splitlines()[0][:300] if text.strip() else ""


def solid_verdict(check, what):
    if "error" in check:
        return "FAIL", "%s: checker could not read it: %s" % (what, check["error"])
    if not check.get("valid"):
        return "FAIL", "%s invalid: %s" % (what, "; ".join(check.get("defects", [])))
    return None


def fmt(x, digits=3):
    return "%.*g" % (digits, x)


def fidelity(runner, src, diagonal, outputs, voxel, extra=()):
    """The input's distance to what a command wrote (corpus_check cover), as
    a figure and a problem (None when it is the input's model). Far is 1% of
    the diagonal, or 3 of the command's voxels where that is more (the
    accuracy asked for); an output is far from its input when more than 2% of
    the input's surface is far from it, or the mean distance is over 0.1% of
    the diagonal (0.5 voxel where that is more). The largest distance is a
    figure: a feature thinner than the voxel may vanish."""
    far = max(FIDELITY_FAR_RATIO * diagonal, FIDELITY_FAR_VOXELS * (voxel or 0))
    mean = max(FIDELITY_MEAN_RATIO * diagonal, FIDELITY_MEAN_VOXELS * (voxel or 0))
    # Slits narrower than two of the command's voxels may close, as its own
    # fidelity gate allows (docs/reports.md#fidelity).
    cover = runner.check(["cover", src, "--fit", str(runner.args.fit_mm), "--far", repr(far),
                          "--gap", repr(2 * (voxel or 0))] + list(extra) + list(outputs))
    if "error" in cover:
        return cover, "fidelity not measured: " + cover["error"], "fidelity not measured"
    fig = "input to output: %s%% farther than %s mm, max %s%% / mean %s%% of the diagonal" % (
        fmt(100 * cover["far_fraction"]), fmt(far), fmt(100 * cover["max_ratio"]), fmt(100 * cover["mean_ratio"]))
    if cover["far_fraction"] > FIDELITY_FAR_SHARE or cover["mean"] > mean:
        return cover, "far from the input (%s, %s)" % (fig, cover["max_side"]), fig
    return cover, None, fig


def check_contradictions(rep, code, facts, fit_mm):
    """What in a `check` report is missing or contradicts what the harness
    knows apart from fabvdb: the exit code (5 exactly when the verdict is
    fail), a verdict that is the worst of every check's status, the fitted
    size (longest side at most --fit, box diagonal = the checker's), and the
    checker's facts on the input as a binary STL stores it (closed 2-manifold
    and consistently oriented, shell count, volume of a clean solid)."""
    problems = []
    checks = rep.get("checks") if isinstance(rep.get("checks"), dict) else {}
    missing = [n for n in CHECK_NAMES if not isinstance(checks.get(n), dict)
               or checks[n].get("status") not in CHECK_STATUSES]
    if rep.get("verdict") not in CHECK_STATUSES or missing:
        return ["report without %s" % ", ".join((["a verdict"] if rep.get("verdict") not in CHECK_STATUSES else [])
                                                + ["check " + n for n in missing])]
    worst = max((c["status"] for c in checks.values() if c.get("status") in CHECK_STATUSES),
                key=CHECK_STATUSES.index)
    if rep["verdict"] != worst:
        problems.append("verdict %s, worst check %s" % (rep["verdict"], worst))
    if (code == CHECK_FAIL_EXIT) != (rep["verdict"] == "fail"):
        problems.append("exit %d with verdict %s" % (code, rep["verdict"]))
    # --fit scales the box of every vertex the file lists; the units check,
    # like the checker, boxes the vertices its triangles use, which may lie
    # inside (vertices no triangle uses).
    units = checks["units"]
    size = units.get("size") or [0, 0, 0]
    longest = max(size)
    # Vertices no triangle uses can make the fitted triangles small (sliver_tet:
    # 0.95 mm): then the units check may warn, as the checker's diagonal says.
    small = (facts.get("diagonal") or fit_mm) < 10.0
    if longest > (1 + SIZE_TOLERANCE) * fit_mm or (units["status"] != "pass" and not small):
        problems.append("units: longest side %s mm (%s) after --fit %gmm" % (fmt(longest, 7), units["status"], fit_mm))
    diagonal = facts.get("diagonal")
    report_diagonal = sum(x * x for x in size) ** 0.5
    if diagonal and abs(report_diagonal - diagonal) > SIZE_TOLERANCE * fit_mm:
        problems.append("units: box diagonal %s mm, the checker's %s mm" % (fmt(report_diagonal, 7), fmt(diagonal, 7)))
    # The checker rounds to float and welds equal corners, which collapses
    # triangles whose corners differ only beyond float (cube_gears_prod_req:
    # 92, as a 3MF's decimal coordinates are read as doubles); its topology
    # is then another mesh's.
    mesh = checks["mesh"]
    if "closed_two_manifold" in facts and facts.get("degenerate_triangles") == 0:
        said = bool(mesh.get("closed")) and bool(mesh.get("manifold")) and bool(mesh.get("consistently_oriented"))
        if said != facts["closed_two_manifold"]:
            problems.append("mesh: closed, manifold and oriented %s, the checker %s" % (
                "yes" if said else "no", "yes" if facts["closed_two_manifold"] else "no"))
        elif said and mesh.get("shells") != facts.get("shells"):
            problems.append("mesh: %s shells, the checker %s" % (mesh.get("shells"), facts.get("shells")))
    if facts.get("valid") and not encloses_nothing(facts):  # a flat sliver's volume is float noise
        volume = mesh.get("volume")
        if not isinstance(volume, (int, float)) or abs(volume - facts["volume"]) > VOLUME_TOLERANCE * facts["volume"]:
            problems.append("mesh: volume %s mm^3, the checker %s" % (volume, fmt(facts["volume"], 7)))
    return problems


def check_figure(rep):
    """The verdict, each check's status that is not a pass, and the voxel."""
    checks = rep.get("checks") if isinstance(rep.get("checks"), dict) else {}
    flagged = ["%s %s" % (n, checks[n]["status"]) for n in CHECK_NAMES
               if isinstance(checks.get(n), dict) and checks[n].get("status") in ("warn", "fail")]
    return "%s%s, voxel %s mm" % (rep.get("verdict"), " (" + ", ".join(flagged) + ")" if flagged else "",
                                  fmt(rep.get("voxel_size") or 0))


def file_digest(path):
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def run_identity(args):
    """What a record must share to be kept by --resume: the digests of the
    fabvdb binary, the libfabvdb it loads (ldd, under this environment) and
    the checker, and every recipe setting that changes a cell."""
    binaries = [os.path.abspath(args.fabvdb), args.checker]
    linked = subprocess.run(["ldd", os.path.abspath(args.fabvdb)], capture_output=True, text=True).stdout
    binaries += sorted(m.group(1) for m in re.finditer(r"libfabvdb\S* => (\S+)", linked))
    return {"binaries": {os.path.basename(path): file_digest(path) for path in binaries},
            "recipe": {"fit_mm": args.fit_mm, "wall_mm": WALL_MM, "time_cap_s": args.time_cap,
                       "mem_cap": args.mem_cap, "check_cap_s": args.check_cap, "inside_out": args.inside_out,
                       "subset": args.subset, "molds": not args.no_molds}}


def resumable(row, args, identity):
    """The model's record, when it holds every wanted command from a run of
    the same identity; None otherwise."""
    try:
        with open(os.path.join(args.out, "runs", row["file"], "record.json")) as f:
            rec = json.load(f)
    except (OSError, ValueError):
        return None
    if rec.get("identity") != identity or any(c not in rec.get("runs", {}) for c in args.commands):
        return None
    return rec


def process_model(row, args, runner, with_mold):
    name = row["file"]
    original = os.path.join(args.corpus, name)
    src = original
    work = os.path.join(args.out, "runs", name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if args.inside_out:
        # The same model stored inside out: every triangle reversed, as OBJ
        # (every vertex as read, full precision), named after the original.
        src = os.path.join(work, os.path.splitext(name)[0] + ".inside-out.obj")
        flipped = runner.check(["flip", original, src])
        if "error" in flipped:
            raise RuntimeError("%s: could not turn it inside out: %s" % (name, flipped["error"]))
    wanted = set(args.commands)
    fabvdb = os.path.abspath(args.fabvdb)
    fit = ["--fit", "%gmm" % args.fit_mm]
    record = {"model": name, "category": row["category"], "triangles": row["triangles"],
              "closed": row["closed"], "inside_out": args.inside_out, "runs": {}}
    facts = runner.check(["input", src, "--fit", str(args.fit_mm)])
    record["input_check"] = facts
    closed_input = row["closed"] == "yes"

    def cell(command, result, figure, run, **extra):
        c = {"result": result, "figure": figure}
        if run:
            c.update({"seconds": run["seconds"], "peak_mib": run["peak_mib"], "exit": run["exit"],
                      "command": run["command"]})
            if run["exit"] != 0:
                c["message"] = first_line(run["stderr"])
        c.update(extra)
        record["runs"][command] = c
        return c

    # info: on the file as it is (no --fit), so unit warnings can show.
    r = runner.run([fabvdb, "info", src, "--report", "info.json"], work, "info") if "info" in wanted else None
    if r is None:
        pass
    elif r["exit"] == 0:
        try:
            rep = json.load(open(os.path.join(work, "info.json")))
            warn = [l for l in r["stderr"].splitlines() if "warn" in l.lower()]
            dropped = threemf_repeated_corner_triangles(original) if original.lower().endswith(".3mf") else 0
            if rep.get("triangles") != row["triangles"] - dropped:
                cell("info", "FAIL", "%s triangles, manifest %d" % (rep.get("triangles"), row["triangles"]), r)
            else:
                cell("info", "ok", "%d tri%s, closed %s%s" % (
                    rep["triangles"], " (%d with a repeated corner dropped by lib3mf)" % dropped if dropped else "",
                    rep.get("closed"), ", %d warning(s)" % len(warn) if warn else ""), r, warnings=warn)
        except (OSError, ValueError) as e:
            cell("info", "FAIL", "exit 0 but no readable report (%s)" % e, r)
    else:
        v, why = judge_failure(r, src, None, {}, False)
        cell("info", v, why, r)

    # check: scaled like every other command (its thresholds are millimetres,
    # and its voxel is kept between a quarter and a half of the minimum wall,
    # so an unscaled part in metres or at 2 m would be measured at one voxel
    # or run out of the caps); its report's figures against the checker's.
    r = runner.run([fabvdb, "check", src] + fit + ["--process", CHECK_PROCESS, "--report", "check.json"], work,
                   "check") if "check" in wanted else None
    if r is None:
        pass
    elif r["exit"] in (0, CHECK_FAIL_EXIT):
        try:
            rep = json.load(open(os.path.join(work, "check.json")))
        except (OSError, ValueError) as e:
            rep, problems = None, ["exit %d but no readable report (%s)" % (r["exit"], e)]
        if rep is not None:
            problems = check_contradictions(rep, r["exit"], facts, args.fit_mm)
        fig = check_figure(rep) if rep is not None else ""
        cell("check", "FAIL" if problems else "ok", "; ".join(problems) + " (" + fig + ")" if problems else fig, r,
             verdict=rep.get("verdict") if isinstance(rep, dict) else None,
             statuses={n: rep["checks"][n].get("status") for n in CHECK_NAMES
                       if isinstance(rep, dict) and n in rep.get("checks", {})})
    else:
        v, why = judge_failure(r, src, None, facts, closed_input)
        cell("check", v, why, r)

    # repair
    out = os.path.join(work, "repaired.stl")
    r = runner.run([fabvdb, "repair", src] + fit + ["-o", out, "--report", "repair.json"], work, "repair") \
        if "repair" in wanted else None
    if r is None:
        pass
    elif r["exit"] == 0:
        chk = runner.check(["solid", out, "--reference", src, "--fit", str(args.fit_mm)])
        bad = solid_verdict(chk, "output")
        if bad:
            cell("repair", bad[0], bad[1], r, check=chk)
        else:
            rep = json.load(open(os.path.join(work, "repair.json")))
            voxel = rep.get("voxel_size") or 0
            h = max(chk["input_to_output"]["max"], chk["output_to_input"]["max"])
            hv = h / voxel if voxel else float("nan")
            fig = "Hausdorff %s voxel (%s mm), %d tri" % (fmt(hv), fmt(h), chk["triangles"])
            cover, far, ffig = fidelity(runner, src, chk["input_diagonal"], [out], voxel)
            fig += ", " + ffig
            if far:
                cell("repair", "FAIL", far, r, check=chk, fidelity=cover, hausdorff_voxels=hv)
            elif facts.get("valid"):
                kept = h <= KEPT_TOLERANCE * chk["diagonal"] and chk["triangles"] == facts["triangles"]
                if not kept:
                    cell("repair", "FAIL", "clean solid not kept as it is (%s; input %d tri)" %
                         (fig, facts["triangles"]), r, check=chk, fidelity=cover, hausdorff_voxels=hv)
                else:
                    cell("repair", "ok", "kept, " + fig, r, check=chk, fidelity=cover, hausdorff_voxels=hv)
            else:
                cell("repair", "ok", fig, r, check=chk, fidelity=cover, hausdorff_voxels=hv)
    else:
        v, why = judge_failure(r, src, out, facts, closed_input)
        cell("repair", v, why, r)
    if "hollow" not in wanted and "drain" not in wanted and "decompose" not in wanted:
        return record

    # hollow
    out = os.path.join(work, "hollow.stl")
    r = runner.run([fabvdb, "hollow", src] + fit + ["--wall", "%gmm" % WALL_MM, "-o", out, "--report",
                                                    "hollow.json"], work, "hollow") if "hollow" in wanted else None
    if r is None:
        pass
    elif r["exit"] == 0:
        chk = runner.check(["solid", out, "--reference", src, "--fit", str(args.fit_mm), "--cavity-wall"])
        bad = solid_verdict(chk, "output")
        if bad:
            cell("hollow", bad[0], bad[1], r, check=chk)
        else:
            rep = json.load(open(os.path.join(work, "hollow.json")))
            cavities = chk.get("cavity_shells", 0)
            reported = rep.get("cavity_count")
            voxel = rep.get("voxel_size") or 0
            outer = chk["input_to_output"]["max"]
            fig = "%d cavities" % cavities
            verdict, why = "ok", None
            if reported is not None and reported != cavities:
                verdict, why = "FAIL", "report says %s cavities, the file has %d" % (reported, cavities)
            if cavities:
                wall = chk["wall"]
                fig += ", wall min %s / median %s mm" % (fmt(wall["min"]), fmt(wall["median"]))
                if wall["min"] < WALL_TOLERANCE * WALL_MM:
                    verdict, why = "FAIL", "wall %s mm < %s mm" % (fmt(wall["min"]), fmt(WALL_TOLERANCE * WALL_MM))
            else:
                fig += " (solid" + (", warned)" if "warn" in r["stderr"].lower() else ", no warning)")
            fig += ", input to outer surface %s voxel" % fmt(outer / voxel if voxel else float("nan"))
            if facts.get("valid") and voxel and outer > voxel:
                verdict, why = "FAIL", "clean input's surface moved %s voxel" % fmt(outer / voxel)
            cover, far, ffig = fidelity(runner, src, chk["input_diagonal"], [out], voxel)
            fig += ", outer surface: " + ffig
            if far:
                verdict, why = "FAIL", far
            cell("hollow", verdict, why + " (" + fig + ")" if why else fig, r, check=chk, fidelity=cover)
    else:
        v, why = judge_failure(r, src, out, facts, closed_input)
        cell("hollow", v, why, r)

    # drain, then powder-sim on what it wrote
    out = os.path.join(work, "drained.stl")
    r = runner.run([fabvdb, "drain", src] + fit + ["--wall", "%gmm" % WALL_MM, "--holes", "auto", "-o", out,
                                                   "--report", "drain.json"], work, "drain") if "drain" in wanted else None
    drained = False
    if r is None:
        pass
    elif r["exit"] == 0:
        chk = runner.check(["solid", out])
        bad = solid_verdict(chk, "output")
        rep = json.load(open(os.path.join(work, "drain.json")))
        holes = len(rep.get("holes", []))
        predicted = rep.get("predicted_residual_fraction")
        if bad:
            cell("drain", bad[0], bad[1], r, check=chk)
        else:
            fig = "%d holes" % holes
            if predicted is not None:
                fig += ", predicted residual %s%%" % fmt(100 * predicted)
            # Each hole's drilled segment and mouth, and each cavity drain
            # filled, are left out of the fidelity.
            mouths = []
            for c in rep.get("filled_cavities", []):
                mouths += ["--exempt", "%.17g,%.17g,%.17g,%.17g" % (c["center"][0], c["center"][1], c["center"][2],
                                                                     c["radius"])]
            for h in rep.get("holes", []):
                c, a, depth = h["center"], h["axis"], h["depth"]
                mouths += ["--exempt", "%.17g,%.17g,%.17g,%.17g" % (
                    c[0] + 0.5 * depth * a[0], c[1] + 0.5 * depth * a[1], c[2] + 0.5 * depth * a[2],
                    0.5 * depth + h["diameter"])]
            cover, far, ffig = fidelity(runner, src, facts.get("diagonal") or 0, [out], rep.get("voxel_size"), mouths)
            fig += ", " + ffig
            cell("drain", "FAIL" if far else "ok", far + " (" + fig + ")" if far else fig, r, check=chk,
                 fidelity=cover)
            drained = holes > 0 and not far
        if not bad and not drained:
            cell("powder-sim", "n/a", "drained part far from the input" if holes else "no holes (no cavity)", None)
    else:
        v, why = judge_failure(r, src, out, facts, closed_input)
        cell("drain", v, why, r)
        cell("powder-sim", "n/a", "no drained part", None)
    if drained and "powder-sim" in wanted:
        r = runner.run([fabvdb, "powder-sim", out, "--holes-from", "drain.json", "--report", "sim.json"], work,
                       "powder-sim")
        if r["exit"] == 0:
            try:
                sim = json.load(open(os.path.join(work, "sim.json")))
                cell("powder-sim", "ok", "residual %s%% (predicted %s%%)" %
                     (fmt(100 * sim["residual_fraction"]), fmt(100 * (predicted or 0))), r,
                     residual_fraction=sim["residual_fraction"], predicted_fraction=predicted)
            except (OSError, ValueError, KeyError) as e:
                cell("powder-sim", "FAIL", "exit 0 without a readable report (%s)" % e, r)
        else:
            v, why = judge_failure(r, out, None, {}, False)
            cell("powder-sim", v, why, r)

    if not with_mold or "decompose" not in wanted:
        return record

    # decompose, then mold from that decomposition
    dec = os.path.join(work, "decompose")
    r = runner.run([fabvdb, "decompose", src] + fit + ["-o", dec, "--report", "decompose.json"], work, "decompose")
    decomposed = False
    if r["exit"] == 0:
        chk = runner.check(["decomposition", os.path.join(dec, "decomposition.json")])
        try:
            doc = json.load(open(os.path.join(dec, "decomposition.json")))
            parts, energy, gamma = len(doc["parts"]), doc["total_moldability_energy"], doc["gamma"]
            fig = "%d parts, energy %s (gamma %s)" % (parts, fmt(energy), fmt(gamma))
            if "error" in chk or not chk.get("valid"):
                cell("decompose", "FAIL", "decomposition.json fails the checks (%s)" %
                     chk.get("error", "see the checker's stderr"), r, check=chk)
            elif energy > gamma:
                cell("decompose", "FAIL", "over gamma: " + fig, r, check=chk)
            else:
                cell("decompose", "ok", fig, r, check=chk)
            decomposed = True
        except (OSError, ValueError, KeyError) as e:
            cell("decompose", "FAIL", "exit 0 without a readable decomposition.json (%s)" % e, r)
    else:
        v, why = judge_failure(r, src, dec, facts, closed_input)
        cell("decompose", v, why, r)
    if "mold" not in wanted:
        return record
    if not decomposed:
        cell("mold", "n/a", "no decomposition", None)
        return record
    mold = os.path.join(work, "mold")
    r = runner.run([fabvdb, "mold", src] + fit + ["--decomposition", os.path.join(dec, "decomposition.json"), "-o",
                                                  mold, "--report", "mold.json"], work, "mold")
    if r["exit"] != 0:
        v, why = judge_failure(r, src, mold, facts, closed_input)
        cell("mold", v, why, r)
        return record
    try:
        rep = json.load(open(os.path.join(work, "mold.json")))
        parts = rep["parts"]
    except (OSError, ValueError, KeyError) as e:
        cell("mold", "FAIL", "exit 0 without a readable report (%s)" % e, r)
        return record
    problems, part_files, checks = [], [], []
    for part in parts:
        d = part["parting_direction"]
        f = os.path.join(mold, part["file"])
        part_files.append(f)
        chk = runner.check(["solid", f, "--direction", "%.17g,%.17g,%.17g" % tuple(d)])
        checks.append(chk)
        bad = solid_verdict(chk, part["file"])
        if bad:
            problems.append(bad[1])
        elif chk["height_field"]["lines_over_two"] or chk["height_field"]["odd_lines"]:
            problems.append("%s not a double height field along its direction: %d of %d lines cross it more than "
                            "twice" % (part["file"], chk["height_field"]["lines_over_two"],
                                       chk["height_field"]["lines"]))
        for key in ("top_file", "bottom_file"):
            piece = os.path.join(mold, part[key])
            pchk = runner.check(["solid", piece])
            checks.append(pchk)
            bad = solid_verdict(pchk, part[key])
            if bad:
                problems.append(bad[1])
    cover = runner.check(["cover", src, "--fit", str(args.fit_mm)] + part_files)
    if "error" in cover:
        problems.append("faithfulness not measured: " + cover["error"])
        fig = "%d parts" % len(parts)
    else:
        fig = "%d parts, input to parts max %s%% (%s, part %s) / mean %s%% of the diagonal" % (
            len(parts), fmt(100 * cover["max_ratio"]), cover["max_side"], cover["max_part"],
            fmt(100 * cover["mean_ratio"]))
        if cover.get("enclosed_samples"):
            fig += " (%d enclosed input samples left out)" % cover["enclosed_samples"]
        if cover["max_ratio"] > MOLD_MAX_RATIO or cover["mean_ratio"] > MOLD_MEAN_RATIO:
            problems.append("not faithful: " + fig)
    if problems:
        cell("mold", "FAIL", "; ".join(problems[:4]) + (" (+%d more)" % (len(problems) - 4) if len(problems) > 4
                                                          else ""), r, checks=checks, cover=cover)
    else:
        cell("mold", "ok", fig, r, checks=checks, cover=cover)
    return record


def write_tables(args, rows, selected):
    records = []
    for row in rows:
        path = os.path.join(args.out, "runs", row["file"], "record.json")
        if row["file"] in selected and os.path.exists(path):
            records.append(json.load(open(path)))
    summary = {c: {"ok": 0, "refused": 0, "FAIL": 0, "n/a": 0} for c in COMMANDS}
    failures = []
    for rec in records:
        for c, cellv in rec["runs"].items():
            summary[c][cellv["result"]] += 1
            if cellv["result"] == "FAIL":
                failures.append((rec["model"], c, cellv))
    statuses = check_status_counts(records)
    doc = {"generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
           "recipe": {"fit_mm": args.fit_mm, "wall_mm": WALL_MM, "holes": "auto", "time_cap_s": args.time_cap,
                      "mem_cap": args.mem_cap, "subset": args.subset, "molds": not args.no_molds,
                      "inside_out": args.inside_out, "commands": args.commands,
                      "fidelity": {"far_ratio": FIDELITY_FAR_RATIO, "mean_ratio": FIDELITY_MEAN_RATIO,
                                   "far_voxels": FIDELITY_FAR_VOXELS, "far_share": FIDELITY_FAR_SHARE,
                                   "mean_voxels": FIDELITY_MEAN_VOXELS}},
           "summary": summary, "check_statuses": statuses, "models": records}
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump(doc, f, indent=1)
    lines = ["# fabvdb corpus run", "",
             "Generated %s by `python3 bench/corpus/run.py %s`. Recipe: `--fit %gmm`, wall %g mm, holes auto; caps "
             "%d s and %s per run. Cells: result · key figure · seconds · peak MiB." %
             (doc["generated"], args.argv_text, args.fit_mm, WALL_MM, args.time_cap, args.mem_cap), "",
             "| command | ok | refused | FAIL | n/a |", "|---|---:|---:|---:|---:|"]
    for c in COMMANDS:
        s = summary[c]
        lines.append("| %s | %d | %d | %d | %d |" % (c, s["ok"], s["refused"], s["FAIL"], s["n/a"]))
    if any(sum(v.values()) for v in statuses.values()):
        lines += ["", "`check` (%s) per check: models that pass, warn, fail." % CHECK_PROCESS, "",
                  "| check | pass | warn | fail |", "|---|---:|---:|---:|"]
        for n in ["verdict"] + CHECK_NAMES:
            lines.append("| %s | %d | %d | %d |" % (n, statuses[n]["pass"], statuses[n]["warn"], statuses[n]["fail"]))
    lines += ["", "| model | category | triangles | " + " | ".join(COMMANDS) + " |",
              "|---|---|---:|" + "---|" * len(COMMANDS)]
    for rec in records:
        cells = []
        for c in COMMANDS:
            v = rec["runs"].get(c)
            if not v:
                cells.append("")
                continue
            text = "**%s** %s" % (v["result"], v["figure"] or "")
            if v.get("seconds") is not None:
                text += " · %.1f s" % v["seconds"]
            if v.get("peak_mib") is not None:
                text += " · %d MiB" % v["peak_mib"]
            cells.append(text.replace("|", "/").replace("\n", " "))
        lines.append("| `%s` | %s | %d | %s |" % (rec["model"], rec["category"], rec["triangles"], " | ".join(cells)))
    lines += ["", "## Failures", ""]
    for model, c, v in failures:
        lines.append("- `%s` %s: %s — `%s`" % (model, c, v["figure"], v.get("command", "")))
    with open(os.path.join(args.out, "results.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return summary, failures


def check_status_counts(records):
    """Per check of `check` (and its verdict), how many models pass, warn, fail."""
    counts = {n: {v: 0 for v in CHECK_STATUSES} for n in ["verdict"] + CHECK_NAMES}
    for rec in records:
        c = rec["runs"].get("check", {})
        if c.get("verdict") in CHECK_STATUSES:
            counts["verdict"][c["verdict"]] += 1
        for n, v in (c.get("statuses") or {}).items():
            if v in CHECK_STATUSES:
                counts[n][v] += 1
    return counts


def parse_size(text):
    m = re.fullmatch(r"(\d+)([KMG]?)", text.strip().upper())
    if not m:
        raise argparse.ArgumentTypeError("size like 8G or 512M")
    return int(m.group(1)) * {"": 1, "K": 1 << 10, "M": 1 << 20, "G": 1 << 30}[m.group(2)]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description="Run every fabvdb command on the corpus and check every output "
                                "independently (bench/corpus/README.md).")
    p.add_argument("--fabvdb", required=True, help="the fabvdb binary")
    p.add_argument("--checker", required=True, help="the corpus_check binary (build/bench/corpus_check)")
    p.add_argument("--corpus", default=os.path.normpath(os.path.join(here, "../../../shared/data/corpus")))
    p.add_argument("--out", required=True, help="output folder (results.md, results.json, runs/)")
    p.add_argument("--subset", choices=["all", "smallest20"], default="all",
                   help="all: every mesh (decompose+mold on the 40 of the mold rule); smallest20: the 20 meshes "
                   "with the fewest triangles, every command on each")
    p.add_argument("--no-molds", action="store_true",
                   help="run neither decompose nor mold (the ctest of the fast subset: info, check, repair, hollow, "
                   "drain and powder-sim)")
    p.add_argument("--only", nargs="*", help="rerun just these models (their rows are refreshed)")
    p.add_argument("--category", nargs="*", choices=sorted(MOLD_SHARE),
                   help="run just the models of these categories (their rows are refreshed)")
    p.add_argument("--commands", default=",".join(COMMANDS),
                   help="comma-separated commands to run (default all; powder-sim needs drain, mold decompose)")
    p.add_argument("--inside-out", action="store_true",
                   help="run every command on each model turned inside out (every triangle reversed, written "
                   "as OBJ by corpus_check flip); use its own --out")
    p.add_argument("--jobs", type=int, default=2, help="models run at once")
    p.add_argument("--time-cap", type=int, default=120, help="seconds per command run")
    p.add_argument("--mem-cap", default="8G", help="address-space cap per command run")
    p.add_argument("--fit", dest="fit_mm", type=float, default=60.0,
                   help="millimetres the longest side of each model is scaled to (--fit of every command)")
    p.add_argument("--check-cap", type=int, default=600, help="seconds per checker run")
    p.add_argument("--resume", action="store_true",
                   help="keep each model whose record came from the same binaries (by digest) and recipe and "
                   "holds every wanted command; run the others")
    p.add_argument("--tables-only", action="store_true",
                   help="run nothing: write the tables from the records already in OUT/runs")
    args = p.parse_args()
    args.mem_cap_bytes = parse_size(args.mem_cap)
    args.commands = [c for c in args.commands.split(",") if c]
    unknown = [c for c in args.commands if c not in COMMANDS]
    if unknown:
        p.error("unknown command(s) in --commands: " + ", ".join(unknown))
    args.argv_text = " ".join(sys.argv[1:])
    args.checker = os.path.abspath(args.checker)
    args.corpus = os.path.abspath(args.corpus)
    os.makedirs(os.path.join(args.out, "runs"), exist_ok=True)
    rows = read_manifest(args.corpus)
    if args.subset == "smallest20":
        selected_rows = smallest(rows, 20)
        mold_set = {r["file"] for r in selected_rows}
    else:
        selected_rows = rows
        mold_set = mold_selection(rows)
    if args.no_molds:
        mold_set = set()
    selected = {r["file"] for r in selected_rows}
    # Smallest first, so an interrupted run has covered the most models.
    todo = sorted((r for r in selected_rows if (not args.only or r["file"] in args.only) and
                   (not args.category or r["category"] in args.category)),
                  key=lambda r: (r["triangles"], r["file"]))
    runner = Runner(args)

    identity = run_identity(args)

    def one(row):
        if args.resume and resumable(row, args, identity):
            print("%-40s kept (--resume)" % row["file"], flush=True)
            return []
        rec = process_model(row, args, runner, row["file"] in mold_set)
        rec["identity"] = identity
        with open(os.path.join(args.out, "runs", row["file"], "record.json"), "w") as f:
            json.dump(rec, f, indent=1)
        bad = [c for c, v in rec["runs"].items() if v["result"] == "FAIL"]
        print("%-40s %s" % (row["file"], " ".join("%s:%s" % (c, v["result"]) for c, v in rec["runs"].items())),
              flush=True)
        return bad

    if not args.tables_only:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            list(pool.map(one, todo))
    summary, failures = write_tables(args, rows, selected)
    for c in COMMANDS:
        s = summary[c]
        print("%-11s ok %3d  refused %3d  FAIL %3d  n/a %3d" % (c, s["ok"], s["refused"], s["FAIL"], s["n/a"]))
    print("tables: %s, %s" % (os.path.join(args.out, "results.md"), os.path.join(args.out, "results.json")))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
