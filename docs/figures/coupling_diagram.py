#!/usr/bin/env python3
"""Draws docs/figures/coupling_diagram.svg, the connection diagram of the moored platform
(docs/coupling.md), from the system files themselves: the connections and their units from
fmu-pack/system/SystemStructure.ssd, the OSP variable groups from
modelDescription/SlowDrift_OspModelDescription.xml, the parameter values from the SSD's
parameter bindings (none: the system's SlowDrift.fmu has no internal spring by
construction). So the picture shows what the files say. Standard library only; the
output is the same bytes on every run (tests/clients/test_system_files.py checks that the
committed file is this script's output).

Usage: python3 docs/figures/coupling_diagram.py [OUT.svg]
"""

import os
import sys
import xml.etree.ElementTree as ET
from xml.sax.saxutils import escape

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SSD = os.path.join(ROOT, "fmu-pack", "system", "SystemStructure.ssd")
OSP_MD = os.path.join(ROOT, "modelDescription", "SlowDrift_OspModelDescription.xml")
OUT = os.path.join(ROOT, "docs", "figures", "coupling_diagram.svg")
NS = {
    "ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
    "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
    "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues",
    "md": "https://open-simulation-platform.com/OspModelDescription/1.0.1",
}
GROUP_FILL = {"position": "#e8f1fb", "heading": "#eaf6ea", "linearMechanicalPort": "#fdf1e3",
              "angularMechanicalPort": "#f5eafb"}
FONT = "font-family=\"DejaVu Sans, Arial, sans-serif\""


def read_system():
    """[(slowdrift variable, mooring variable, unit, direction)], parameter values, and
    {SlowDrift variable: top-level OSP group}."""
    root = ET.parse(SSD).getroot()
    system = root.find("ssd:System", NS)
    units = {}
    params = []
    for c in system.find("ssd:Elements", NS):
        for k in c.findall("ssd:Connectors/ssd:Connector", NS):
            units[(c.get("name"), k.get("name"))] = list(k)[0].get("unit")
        for p in c.findall(".//ssv:Parameter", NS):
            v = list(p)[0]
            params.append((c.get("name"), p.get("name"), v.get("value"), v.get("unit")))
    rows = []
    for c in system.find("ssd:Connections", NS):
        a = (c.get("startElement"), c.get("startConnector"))
        b = (c.get("endElement"), c.get("endConnector"))
        if a[0] == "slowdrift":
            rows.append((a[1], b[1], units[a], "to mooring"))
        else:
            rows.append((b[1], a[1], units[a], "to slowdrift"))
    group_of = {}
    for g in ET.parse(OSP_MD).getroot().find("md:VariableGroups", NS):
        for v in g.iter("{%s}Variable" % NS["md"]):
            group_of[v.get("ref")] = g.get("name")
    return rows, params, group_of


def text(x, y, s, size=13, anchor="start", weight="normal", fill="#222"):
    return (f'<text x="{x}" y="{y}" {FONT} font-size="{size}" text-anchor="{anchor}" '
            f'font-weight="{weight}" fill="{fill}">{escape(s)}</text>')


def arrow(x1, x2, y, colour):
    head = 9 if x2 > x1 else -9
    return (f'<line x1="{x1}" y1="{y}" x2="{x2 - head}" y2="{y}" stroke="{colour}" stroke-width="2"/>'
            f'<polygon points="{x2},{y} {x2 - head},{y - 5} {x2 - head},{y + 5}" fill="{colour}"/>')


def draw(rows, params, group_of):
    groups = {}  # group -> its variables, groups in the order of their first connection
    for sd, _mo, _u, _d in rows:
        groups.setdefault(group_of[sd], []).append(sd)
    groups = list(groups.items())
    order = [v for _g, vs in groups for v in vs]
    rows = sorted(rows, key=lambda r: order.index(r[0]))
    top, pitch = 96, 34
    left, right, box_w = 40, 640, 230
    height = top + pitch * len(rows) + 215
    width = 910
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           text(width / 2, 30, "The moored platform in a co-simulation master "
                "(target/fmu/system/)", 16, "middle", "bold"),
           text(width / 2, 52, "OspSystemStructure.xml and MooredPlatform.ssp: the same "
                f"{len(rows)} connections, 1 s macro step", 13, "middle")]
    y_of = {r[0]: top + 20 + pitch * i for i, r in enumerate(rows)}
    x1, x2 = left + box_w, right
    for name, members in groups:
        y0, y1 = y_of[members[0]] - 22, y_of[members[-1]] + 12
        out.append(f'<rect x="{x1 + 8}" y="{y0}" width="{x2 - x1 - 16}" height="{y1 - y0}" '
                   f'rx="6" fill="{GROUP_FILL.get(name, "#eeeeee")}"/>')
        out.append(text(x1 + 16, y0 + 13, f"OSP group {name}", 11, fill="#555"))
    box_h = pitch * len(rows) + 24
    for x, title, sub in ((left, "SlowDrift.fmu", "slow drift + wave-frequency motion"),
                          (right, "Mooring.fmu", "MoorDyn's lines (spread mooring)")):
        out.append(f'<rect x="{x}" y="{top - 16}" width="{box_w}" height="{box_h}" rx="8" '
                   'fill="#f7f7f7" stroke="#333" stroke-width="1.5"/>')
        out.append(text(x + box_w / 2, top - 24, title, 14, "middle", "bold"))
        out.append(text(x + box_w / 2, top + box_h + 2, sub, 12, "middle", fill="#444"))
    for sd, mo, unit, direction in rows:
        y = y_of[sd]
        out.append(text(left + box_w - 10, y + 4, sd, 13, "end"))
        out.append(text(right + 10, y + 4, mo, 13))
        if direction == "to mooring":
            out.append(arrow(x1, x2, y, "#1f5fa8"))
        else:
            out.append(arrow(x2, x1, y, "#b3541e"))
        out.append(text((x1 + x2) / 2 + 40, y - 4, unit, 11, "middle", fill="#333"))
    y = top + box_h + 34
    if params:
        out.append(text(left, y, "Set by the system:", 12, weight="bold"))
        lines = [f"{comp}.{name} = {value} {unit}" for comp, name, value, unit in params]
    else:
        out.append(text(left, y, "No parameter set by the system:", 12, weight="bold"))
        lines = ["its SlowDrift.fmu is packed with no internal",
                 "spring (stiffness 0): the lines alone moor it."]
    for i, line in enumerate(lines):
        out.append(text(left + 16, y + 18 + 16 * i, line, 12))
    notes = ["Jacobi masters (libcosim, ecos, fmpy's SSP):",
             "both step from t_n; over [t_n, t_n + 1 s] the",
             "platform holds the line force of t_n."]
    for i, s in enumerate(notes):
        out.append(text(left, y + 90 + 15 * i, s, 11, fill="#444"))
    # Sign conventions: inertial X, Y with Z up, theta counter-clockwise.
    ox, oy = 470, y + 120
    out.append(text(ox - 30, y, "Frame and signs (both FMUs):", 12, weight="bold"))
    out.append(arrow(ox, ox + 90, oy, "#222"))
    out.append(f'<line x1="{ox}" y1="{oy}" x2="{ox}" y2="{oy - 81}" stroke="#222" stroke-width="2"/>'
               f'<polygon points="{ox},{oy - 90} {ox - 5},{oy - 81} {ox + 5},{oy - 81}" fill="#222"/>')
    out.append(text(ox + 96, oy + 4, "X", 13, weight="bold"))
    out.append(text(ox - 4, oy - 95, "Y", 13, "middle", weight="bold"))
    out.append(f'<circle cx="{ox}" cy="{oy}" r="4" fill="none" stroke="#222" stroke-width="1.5"/>'
               f'<circle cx="{ox}" cy="{oy}" r="1.2" fill="#222"/>')
    out.append(text(ox - 10, oy + 18, "Z up", 11, "middle"))
    out.append(f'<path d="M {ox + 45} {oy} A 45 45 0 0 0 {ox + 32} {oy - 32}" fill="none" '
               'stroke="#b3541e" stroke-width="1.8"/>'
               f'<polygon points="{ox + 26},{oy - 37} {ox + 37},{oy - 34} {ox + 30},{oy - 25}" '
               'fill="#b3541e"/>')
    out.append(text(ox + 52, oy - 22, "theta, Mz", 11, fill="#b3541e"))
    notes = ["Inertial frame; angles in rad from +X,",
             "counter-clockwise about +Z.",
             "Fx, Fy, Mz: the force of the lines on",
             "the platform at its reference point.",
             "No sign change, no unit conversion."]
    for i, s in enumerate(notes):
        out.append(text(ox + 150, oy - 78 + 15 * i, s, 11))
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main(argv):
    out = argv[1] if len(argv) > 1 else OUT
    svg = draw(*read_system())
    with open(out, "w", encoding="utf-8", newline="\n") as f:
        f.write(svg)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv)
