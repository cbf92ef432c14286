#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Independent reference for the NC export test: renders resources/samples/vmc-profile.json with the
map files in resources/nc/ into tests/data/nc/vmc.<format>.expected, following the rules written in
docs/formats-profile.md (not the C++ code). Run from the repository root:
    /usr/bin/python3 tests/data/nc/make_expected.py
"""
import json
import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
OUT = os.path.join(ROOT, "tests", "data", "nc")
# Unit tokens used by the maps: factor to SI (core/model/Units.h lists the same tokens).
TO_SI = {"1": 1.0, "%": 0.01, "m": 1.0, "mm": 1e-3, "um": 1e-6, "1/s": 1.0, "Hz": 1.0, "V/A": 1.0,
         "Nm*s/rad": 1.0, "ms": 1e-3, "s": 1.0}


def fill(template, variables):
    out = template
    for k, v in variables.items():
        out = out.replace("{" + k + "}", v)
    return out


def nc_value(entry, value_si):
    v = value_si * TO_SI[entry["si_unit"]] / TO_SI[entry["unit"]] * entry.get("scale", 1.0)
    d = entry.get("decimals", 0)
    if d == 0:
        r = math.floor(abs(v) + 0.5) * (1 if v >= 0 else -1)
        return "%d" % r
    s = "%.*f" % (d, v)
    if s.startswith("-") and set(s[1:]) <= set("0."):
        s = s[1:]
    return s


def render(profile, m):
    base = {"machine": profile["machine"]["name"], "family": m["family"], "title": m["title"]}
    axes = profile["axes"]

    def comment(text):
        for f in m.get("comment_forbidden", []):
            text = text.replace(f, " ")
        return fill(m["comment"], dict(base, text=text)) + "\n"

    def axis_vars(v, i):
        return dict(v, axis=axes[i]["name"], axis_index=str(i + 1), axis_index0=str(i))

    def entry_vars(e):
        return dict(base, number=e["number"], key=e["key"], unit=e["unit"])

    t = "".join(fill(h, base) + "\n" for h in m.get("header", []))
    t += comment("AxisTune " + m["title"] + " - machine " + base["machine"])
    t += comment("VERIFY: " + m["verify"])
    layout = m["layout"]
    if layout == "by_axis":
        for i, a in enumerate(axes):
            if m.get("axis_header"):
                t += fill(m["axis_header"], axis_vars(base, i)) + "\n"
            for e in m["parameters"]:
                if e["key"] in a["parameters"]:
                    v = dict(axis_vars(entry_vars(e), i), value=nc_value(e, a["parameters"][e["key"]]))
                    t += fill(e.get("line", m["line"]), v) + "\n"
    else:
        for e in m["parameters"]:
            items = []
            for i, a in enumerate(axes):
                if e["key"] not in a["parameters"]:
                    continue
                v = dict(axis_vars(entry_vars(e), i), value=nc_value(e, a["parameters"][e["key"]]))
                if layout == "by_parameter_per_axis":
                    t += fill(e.get("line", m["line"]), v) + "\n"
                else:
                    items.append(fill(m["axis_item"], v))
            if layout == "by_parameter" and items:
                t += fill(e.get("line", m["line"]), dict(entry_vars(e), axes=m.get("axis_separator", "").join(items))) + "\n"
    mapped = {e["key"] for e in m["parameters"]}
    unmapped = {}
    for a in axes:
        for k in sorted(a["parameters"]):
            if k not in mapped:
                unmapped.setdefault(k, []).append("%s=%.9g" % (a["name"], a["parameters"][k]))
    if unmapped:
        t += comment("UNMAPPED: %d AxisTune parameters have no %s mapping and are NOT in this file; "
                     "set them by hand if the NC has them (SI values):" % (len(unmapped), m["family"]))
        for k in sorted(unmapped):
            t += comment("UNMAPPED " + k + ": " + ", ".join(unmapped[k]))
    t += "".join(fill(f, base) + "\n" for f in m.get("footer", []))
    return t


def main():
    profile = json.load(open(os.path.join(ROOT, "resources", "samples", "vmc-profile.json")))
    for family in ("fanuc", "siemens", "heidenhain"):
        m = json.load(open(os.path.join(ROOT, "resources", "nc", family + ".json")))
        open(os.path.join(OUT, "vmc.%s.expected" % family), "w").write(render(profile, m))
    rows = ["# format=axistune-parameters", "# machine=" + profile["machine"]["name"], "machine,axis,key,value"]
    for a in profile["axes"]:
        for k in sorted(a["parameters"]):
            rows.append("%s,%s,%s,%.17g" % (profile["machine"]["name"], a["name"], k, a["parameters"][k]))
    open(os.path.join(OUT, "vmc.csv.expected"), "w").write("\n".join(rows) + "\n")
    # The profile JSON export is the canonical form: sorted keys, 2-space indent, parameters as floats.
    for a in profile["axes"]:
        a["parameters"] = {k: float(v) for k, v in a["parameters"].items()}
    open(os.path.join(OUT, "vmc.json.expected"), "w").write(json.dumps(profile, indent=2, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
