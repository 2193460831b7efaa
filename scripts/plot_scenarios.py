#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Draw what `clearjoint detect` finds for each configuration of a JSON Lines file.

Runs `clearjoint detect` on the inputs (default examples/scenarios.jsonl, one configuration per
scenario of the paper's Fig. 2, and examples/pin_in_hole_scenarios.jsonl, one per scenario of the
pin-in-hole joint, with exaggerated clearances so that the tilt and the penetration are visible)
and writes one PNG per line, docs/figures/scenario-<id>.png: a side view (the plane
of the bearing axis and the direction the journal leans or is pushed to) and an end view (looking
down the bearing axis from base A). The bearing, the journal's rims and outline, and every contact
the program reports are drawn from the program's own answer and the input poses: nothing is drawn
by hand. For a pin-in-hole line ("joint": "pin_in_hole") the link around the hole takes the
bearing's place and the pin with its stops (heads drawn with a nominal thickness) the journal's. Journal contact points are red dots, bearing contact points blue crosses, crossings
(ends of the penetration arc) small black circles; arrows show the normal (out of the bearing,
fixed display length, not the depth).

    scripts/plot_scenarios.py [--clearjoint PROGRAM] [--tables PROGRAM] [--input FILE ...] [--out DIR]

Each picture is titled with the scenario's label from the library's enum table (ContactScenario,
or PinInHoleScenario for a pin-in-hole line) (what
clearjoint_describe_projections, built beside the program, prints), not in words of its own.

Uses Debian's python3-matplotlib (hence /usr/bin/python3). Each PNG is written to a temporary
file and renamed, so an interrupted run leaves no half-written picture.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402  (after use())

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The program that prints the library's enum tables as JSON (scripts/projections/), whose
# ContactScenario table (PinInHoleScenario for the pin-in-hole joint) gives each scenario's key
# (the answer's spelling) and its label.
DESCRIBE_TABLES = os.path.join("projections", "clearjoint_describe_projections")


MM = 1e3  # the input is in metres; the pictures are labelled in millimetres
RIM_SAMPLES = 360
# Display length of a normal arrow, as a fraction of the bearing radius (a direction, not a size).
NORMAL_ARROW_FRACTION = 0.2
# The pin-in-hole pictures: the link drawn out to this multiple of the hole radius, and each head
# this fraction of the hole length thick (the model has the stops' faces only, not the heads).
LINK_OUTER_FRACTION = 1.8
HEAD_THICKNESS_FRACTION = 0.15
# The enum table naming each joint's scenarios, by the line's "joint" (docs/command-line.md).
SCENARIO_TABLES = {"journal_bearing": "ContactScenario", "pin_in_hole": "PinInHoleScenario"}


# ---- small vector helpers (3-tuples) --------------------------------------------------------
def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def scale(s, a):
    return tuple(s * x for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    return scale(1.0 / norm(a), a)


def perpendicular_part(v, axis_hat):
    return sub(v, scale(dot(v, axis_hat), axis_hat))


def find_program(given):
    if given:
        return given
    for build in ("build", "build-cli"):
        path = os.path.join(REPOSITORY, build, "apps", "clearjoint", "clearjoint")
        if os.access(path, os.X_OK):
            return path
    sys.exit("plot_scenarios: clearjoint not found; build it or pass --clearjoint PROGRAM")


def find_describe_tables(given):
    if given:
        return given
    for build in ("build", "build-cli"):
        path = os.path.join(REPOSITORY, build, DESCRIBE_TABLES)
        if os.access(path, os.X_OK):
            return path
    sys.exit("plot_scenarios: clearjoint_describe_projections not found; build it or pass --tables PROGRAM")


def read_tables(program):
    """The library's enum tables and result field lists, as the program prints them."""
    result = subprocess.run([program], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"plot_scenarios: {program} failed ({result.returncode}):\n{result.stderr}")
    return json.loads(result.stdout)


def scenario_titles(tables, table_type="ContactScenario"):
    """Each scenario's key (the answer's "scenario") to its label, from the table `table_type`
    (ContactScenario, or PinInHoleScenario for the pin-in-hole joint)."""
    for table in tables["enums"]:
        if table["type"] == table_type:
            return {entry["key"]: entry["label"] for entry in table["entries"]}
    sys.exit(f"plot_scenarios: the enum tables hold no {table_type}")


def run_detect(program, input_path):
    """The program's answers, one per non-blank input line."""
    result = subprocess.run([program, "detect", input_path], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"plot_scenarios: clearjoint detect failed ({result.returncode}):\n"
                 f"{result.stdout}{result.stderr}")
    return [json.loads(line) for line in result.stdout.splitlines()]


class View:
    """The drawing frame: e3 along the bearing axis, e2 the direction the journal leans (or is
    offset to, when aligned), e1 = e2 x e3. Side view (e2, e3); end view (e1, e2) seen from A."""

    def __init__(self, bearing, journal):
        """`bearing` and `journal` (or the hole and the pin): dicts with "center" and "axis"."""
        self.origin = tuple(bearing["center"])
        self.e3 = unit(tuple(bearing["axis"]))
        lean = perpendicular_part(tuple(journal["axis"]), self.e3)
        if dot(tuple(journal["axis"]), self.e3) < 0:
            lean = scale(-1.0, lean)
        if norm(lean) < 1e-12 * norm(tuple(journal["axis"])):
            lean = perpendicular_part(sub(tuple(journal["center"]), self.origin), self.e3)
        if norm(lean) == 0.0:
            lean = perpendicular_part((0.0, 1.0, 0.0), self.e3)
            if norm(lean) == 0.0:
                lean = (1.0, 0.0, 0.0)
        self.e2 = unit(lean)
        self.e1 = cross(self.e2, self.e3)

    def side(self, p):
        d = sub(p, self.origin)
        return dot(d, self.e2) * MM, dot(d, self.e3) * MM

    def end(self, p):
        d = sub(p, self.origin)
        return dot(d, self.e1) * MM, dot(d, self.e2) * MM

    def side_direction(self, v):
        return dot(v, self.e2), dot(v, self.e3)

    def end_direction(self, v):
        return dot(v, self.e1), dot(v, self.e2)


def rim_points(center, axis, radius):
    a = unit(axis)
    helper = (1.0, 0.0, 0.0) if abs(a[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = unit(cross(a, helper))
    v = cross(a, u)
    return [add(center, add(scale(radius * math.cos(t), u), scale(radius * math.sin(t), v)))
            for t in (2 * math.pi * k / RIM_SAMPLES for k in range(RIM_SAMPLES + 1))]


def convex_hull(points):
    """Andrew's monotone chain; the journal's outline in a projection is the hull of its rims."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def turn(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and turn(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and turn(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


class Scene:
    """The bearing, the journal and the reported contacts of one line, ready to project."""

    def __init__(self, query, answer):
        bearing, journal = query["bearing"], query["journal"]
        self.answer = answer
        self.view = View(bearing, journal)
        self.ri, self.li = bearing["radius"], bearing["length"]
        self.rj, self.lj = journal["radius"], journal["length"]
        a_hat = unit(tuple(journal["axis"]))
        # "A" is the journal rim facing bearing base A: labels follow the bearing.
        sign = 1.0 if dot(tuple(journal["axis"]), self.view.e3) >= 0 else -1.0
        center = tuple(journal["center"])
        self.rims = {
            "A": rim_points(add(center, scale(sign * self.lj / 2, a_hat)), a_hat, self.rj),
            "B": rim_points(add(center, scale(-sign * self.lj / 2, a_hat)), a_hat, self.rj),
        }

    def draw(self, ax, which, arrow_length, label_contacts):
        """Draw in the side view (which = "side") or the end view ("end")."""
        project = self.view.side if which == "side" else self.view.end
        direction = self.view.side_direction if which == "side" else self.view.end_direction
        r, h = self.ri * MM, self.li / 2 * MM
        if which == "side":
            outline = [(-r, -h), (r, -h), (r, h), (-r, h), (-r, -h)]
        else:
            outline = [(r * math.cos(t), r * math.sin(t))
                       for t in (2 * math.pi * k / RIM_SAMPLES for k in range(RIM_SAMPLES + 1))]
        ax.fill(*zip(*outline), color="#dde6f0", zorder=0)
        ax.plot(*zip(*outline), color="#2b5d8a", lw=1.6, zorder=1)
        hull = convex_hull([project(p) for rim in self.rims.values() for p in rim])
        ax.fill(*zip(*(hull + hull[:1])), color="#f2d7b6", alpha=0.75, zorder=2)
        ax.plot(*zip(*(hull + hull[:1])), color="#8a5a2b", lw=1.0, zorder=3)
        for label, rim in self.rims.items():
            ax.plot(*zip(*[project(p) for p in rim]), color="#8a5a2b",
                    lw=1.2 if label == "A" else 0.8, ls="-" if label == "A" else "--", zorder=3)
        self.draw_contacts(ax, project, direction, arrow_length, label_contacts)

    def draw_contacts(self, ax, project, direction, arrow_length, label_contacts):
        """Every contact of the answer: its points, crossings and normal."""
        for k, contact in enumerate(self.answer["contacts"]):
            pj, pi = tuple(contact["point_journal"]), tuple(contact["point_bearing"])
            ax.plot(*project(pj), "o", color="#c0392b", ms=5, zorder=6)
            ax.plot(*project(pi), "x", color="#1f4e9c", ms=7, mew=1.8, zorder=6)
            for crossing in contact["crossings"]:
                ax.plot(*project(tuple(crossing)), "o", mfc="none", mec="black", ms=5, zorder=5)
            dx, dy = direction(tuple(contact["normal"]))
            if math.hypot(dx, dy) > 0.2:  # skip normals seen end-on
                x, y = project(pi)
                ax.annotate("", (x + arrow_length * dx, y + arrow_length * dy), (x, y),
                            arrowprops=dict(arrowstyle="->", color="#1f4e9c", lw=1.3), zorder=7)
            if label_contacts:
                ax.annotate(str(k + 1), project(pj), textcoords="offset points", xytext=(6, 4),
                            fontsize=9, color="#c0392b", weight="bold", zorder=8)

    def dimensions_text(self):
        r, h = self.ri * MM, self.li / 2 * MM
        return (f"Ri = {r:g} mm, Rj = {self.rj * MM:g} mm, Li = {2 * h:g} mm, "
                f"Lj = {self.lj * MM:g} mm (cr = {self.clearances()[0]:.3g} mm, "
                f"ca = {self.clearances()[1]:.3g} mm)")

    def clearances(self):
        """cr and ca, mm."""
        return (self.ri - self.rj) * MM, (self.li - self.lj) / 2 * MM

    legend = ("red dot: contact point on the journal;  blue cross: contact point on the bearing;  "
              "black circle: rim crossing\narrow: normal (out of the bearing; display length);  "
              "journal rim A solid, rim B dashed")
    face_names = ("base A", "base B")

    def zoom_view(self, contact):
        """The view in which the contact's normal, hence its depth, is seen best."""
        side = math.hypot(*self.view.side_direction(tuple(contact["normal"])))
        end = math.hypot(*self.view.end_direction(tuple(contact["normal"])))
        return "side" if side >= end else "end"


class PinScene(Scene):
    """The link around the hole, the pin with its stops and the reported contacts of a pin-in-hole
    line (docs/command-line.md): the link in the bearing's place, the pin in the journal's."""

    def __init__(self, query, answer):
        hole, pin = query["hole"], query["pin"]
        self.answer = answer
        self.view = View(hole, pin)
        self.ri, self.li, self.rj = hole["radius"], hole["length"], pin["radius"]
        self.stops = [(stop["position"], stop["outer_radius"]) for stop in pin["stops"]]
        a_hat = unit(tuple(pin["axis"]))
        center = tuple(pin["center"])
        head = HEAD_THICKNESS_FRACTION * self.li
        # The shaft from beyond the outermost stop (or well beyond the link) to the other end.
        positions = [s for s, _ in self.stops] + [-0.9 * self.li, 0.9 * self.li]
        low, high = min(positions) - head, max(positions) + head
        self.shaft = [rim_points(add(center, scale(s, a_hat)), a_hat, self.rj) for s in (low, high)]
        # Each head: its face (the stop) and its back, a head thickness beyond, away from P.
        self.heads = [[rim_points(add(center, scale(s, a_hat)), a_hat, r),
                       rim_points(add(center, scale(s + math.copysign(head, s), a_hat)), a_hat, r)]
                      for s, r in self.stops]
        # The stop faces, drawn as the journal rims are: solid for the stop on the A side.
        self.rims = {("A" if dot(a_hat, self.view.e3) * s > 0 else "B") + str(k): rim[0]
                     for k, ((s, _), rim) in enumerate(zip(self.stops, self.heads))}

    def draw(self, ax, which, arrow_length, label_contacts):
        project = self.view.side if which == "side" else self.view.end
        direction = self.view.side_direction if which == "side" else self.view.end_direction
        r, h, outer = self.ri * MM, self.li / 2 * MM, LINK_OUTER_FRACTION * self.ri * MM
        if which == "side":
            parts = [[(r, -h), (outer, -h), (outer, h), (r, h)], [(-r, -h), (-outer, -h), (-outer, h), (-r, h)]]
            for part in parts:
                ax.fill(*zip(*part), color="#dde6f0", zorder=0)
                ax.plot(*zip(*(part + part[:1])), color="#2b5d8a", lw=1.6, zorder=1)
        else:  # the link's face: a ring between the hole and the drawn outline
            ring = [(math.cos(t), math.sin(t)) for t in (2 * math.pi * k / RIM_SAMPLES for k in range(RIM_SAMPLES + 1))]
            ax.fill(*zip(*([(outer * c, outer * s) for c, s in ring] + [(r * c, r * s) for c, s in reversed(ring)])),
                    color="#dde6f0", lw=0, zorder=0)
            for radius in (r, outer):
                ax.plot(*zip(*[(radius * c, radius * s) for c, s in ring]), color="#2b5d8a", lw=1.6, zorder=1)
        for body in [self.shaft] + self.heads:
            hull = convex_hull([project(p) for circle in body for p in circle])
            ax.fill(*zip(*(hull + hull[:1])), color="#f2d7b6", alpha=0.75, zorder=2)
            ax.plot(*zip(*(hull + hull[:1])), color="#8a5a2b", lw=1.0, zorder=3)
        for label, rim in self.rims.items():
            ax.plot(*zip(*[project(p) for p in rim]), color="#8a5a2b",
                    lw=1.2 if label.startswith("A") else 0.8, ls="-" if label.startswith("A") else "--", zorder=3)
        self.draw_contacts(ax, project, direction, arrow_length, label_contacts)

    def dimensions_text(self):
        stops = (", ".join(f"{s * MM:g}" for s, _ in self.stops) + " mm, outer radius " +
                 ", ".join(f"{r * MM:g}" for _, r in self.stops) + " mm") if self.stops else "none"
        return (f"Rh = {self.ri * MM:g} mm, L = {self.li * MM:g} mm, Rp = {self.rj * MM:g} mm, "
                f"stops at {stops}\n(cr = {self.clearances()[0]:.3g} mm, ca = {self.clearances()[1]:.3g} mm)")

    def clearances(self):
        """cr and ca (on each side when centred; that of L/2 with fewer than two stops), mm."""
        if len(self.stops) == 2:
            gap = abs(self.stops[0][0] - self.stops[1][0])
            return (self.ri - self.rj) * MM, (gap - self.li) / 2 * MM
        return (self.ri - self.rj) * MM, self.li / 2 * MM

    legend = ("red dot: contact point on the pin;  blue cross: contact point on the link;  "
              "black circle: crossing bounding the contact's arc\narrow: normal (out of the link; "
              "display length);  stop face on the A side solid, on the B side dashed; heads of nominal thickness")
    face_names = ("face A", "face B")


def scene_of(query, answer):
    return PinScene(query, answer) if query.get("joint") == "pin_in_hole" else Scene(query, answer)


def draw(query, answer, path, title):
    scene = scene_of(query, answer)
    contacts = answer["contacts"]
    r, h = scene.ri * MM, scene.li / 2 * MM
    cr, ca = scene.clearances()

    zooms = len(contacts)
    fig = plt.figure(figsize=(9.6, 8.4 if zooms else 6.4))
    grid = fig.add_gridspec(2 if zooms else 1, max(zooms, 2) * 2,
                            height_ratios=[3.0, 1.25] if zooms else None)
    side = fig.add_subplot(grid[0, : max(zooms, 2)])
    end = fig.add_subplot(grid[0, max(zooms, 2):])
    fig.suptitle(f"{title}   [clearjoint detect: scenario \"{answer['scenario']}\", "
                 f"{answer['certificate']}]\n" + scene.dimensions_text(), fontsize=10)

    arrow = NORMAL_ARROW_FRACTION * r
    scene.draw(side, "side", arrow, label_contacts=True)
    scene.draw(end, "end", arrow, label_contacts=True)
    pin = isinstance(scene, PinScene)
    label_x = (1.0 + LINK_OUTER_FRACTION) / 2 * r if pin else 0.0
    side.text(label_x, h + 0.04 * r, scene.face_names[0], ha="center", va="bottom", color="#2b5d8a", fontsize=9)
    side.text(label_x, -h - 0.04 * r, scene.face_names[1], ha="center", va="top", color="#2b5d8a", fontsize=9)
    margin = 0.3 * r
    width = LINK_OUTER_FRACTION * r if pin else r  # the link drawn around the hole
    height = max([h] + [abs(s) * MM * 1.4 for s, _ in getattr(scene, "stops", [])])
    side.set_xlim(-width - margin, width + margin)
    side.set_ylim(-height - margin, height + margin)
    end.set_xlim(-width - margin, width + margin)
    end.set_ylim(-width - margin, width + margin)
    axis_name = "hole" if pin else "bearing"
    side.set_title(f"side view ({axis_name} axis up), mm", fontsize=9)
    end.set_title(f"end view (from {scene.face_names[0]}), mm", fontsize=9)

    # One zoom per contact, centred between its two points, a window of twice the larger
    # clearance (or more for a deeper contact), so that the penetration can be seen.
    for k, contact in enumerate(contacts):
        ax = fig.add_subplot(grid[1, 2 * k: 2 * k + 2] if zooms > 1 else grid[1, 1:3])
        which = scene.zoom_view(contact)
        half = max(cr, ca, 1.3 * contact["depth"] * MM)
        scene.draw(ax, which, 0.5 * half, label_contacts=False)
        project = scene.view.side if which == "side" else scene.view.end
        (xi, yi), (xj, yj) = (project(tuple(contact[key]))
                              for key in ("point_bearing", "point_journal"))
        cx, cy = 0.5 * (xi + xj), 0.5 * (yi + yj)
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half, cy + half)
        ax.set_title(f"{k + 1}: {contact['type']} at {contact['base']} ({which} view)\n"
                     f"depth {contact['depth'] * MM:.3g} mm, {contact['certificate']}", fontsize=8)
    for ax in fig.axes:
        ax.set_aspect("equal")
        ax.tick_params(labelsize=7)
    fig.text(0.5, 0.005, scene.legend + ("" if contacts else ";  no contact"),
             fontsize=7.5, ha="center", va="bottom", color="#333333")
    fig.subplots_adjust(left=0.06, right=0.98, top=0.9, bottom=0.06, wspace=0.6, hspace=0.3)

    directory = os.path.dirname(path)
    handle, temporary = tempfile.mkstemp(suffix=".png", dir=directory)
    os.close(handle)
    try:
        fig.savefig(temporary, dpi=100)
        os.chmod(temporary, 0o644)  # mkstemp creates it private
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--clearjoint", help="the clearjoint program (default: build*/apps/...)")
    parser.add_argument("--tables", help="the program printing the enum tables (default: build*/%s)"
                        % DESCRIBE_TABLES)
    parser.add_argument("--input", nargs="+", default=[os.path.join(REPOSITORY, "examples", name)
                                                      for name in ("scenarios.jsonl", "pin_in_hole_scenarios.jsonl")])
    parser.add_argument("--out", default=os.path.join(REPOSITORY, "docs", "figures"))
    args = parser.parse_args()

    program = find_program(args.clearjoint)
    tables = read_tables(find_describe_tables(args.tables))
    os.makedirs(args.out, exist_ok=True)
    for input_path in args.input:
        with open(input_path) as f:
            queries = [json.loads(line) for line in f if line.strip()]
        answers = run_detect(program, input_path)
        if len(answers) != len(queries):
            sys.exit(f"plot_scenarios: {len(answers)} answers for {len(queries)} lines of {input_path}")
        for count, (query, answer) in enumerate(zip(queries, answers), start=1):
            if answer.get("id") != query.get("id") or "error" in answer:
                sys.exit(f"plot_scenarios: {input_path}, line {count}: {answer}")
            titles = scenario_titles(tables, SCENARIO_TABLES[query.get("joint", "journal_bearing")])
            path = os.path.join(args.out, f"scenario-{query['id']}.png")
            if answer["scenario"] not in titles:
                sys.exit(f"plot_scenarios: {input_path}, line {count}: scenario {answer['scenario']!r} "
                         "is not in the library's table")
            draw(query, answer, path, titles[answer["scenario"]])
            print(f"[{count}/{len(queries)}] {path}: scenario {answer['scenario']}, "
                  f"{len(answer['contacts'])} contact(s)", flush=True)


if __name__ == "__main__":
    main()
