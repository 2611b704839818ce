"""The CAD data set: mechanical parts modelled with build123d (OpenCASCADE), exported to binary
STL as CAD tools export them (a chordal tolerance relative to the part's size, an angular one
of about 11 degrees: long thin triangles on flat faces, fans on fillets and holes).

Families: plates with holes and slots, trays with pockets, shells with open tops, flanges with
bolt circles, brackets with chamfers and fillets, bosses and standoffs, knurled and threaded
parts, thin ribs. Each family has a few sizes and options, so that the set is not one shape.

    python make_parts.py OUT_DIR        # writes OUT_DIR/<name>.stl, one per part, and a list
"""

import math
import sys
from pathlib import Path

from build123d import (
    Align, Axis, Box, BuildPart, BuildSketch, Circle, Cylinder, GeomType, Helix, Hole, Locations,
    Mode, Plane, PolarLocations, Rectangle, RectangleRounded, RegularPolygon, SlotCenterToCenter, chamfer,
    export_stl, extrude, fillet, offset, sweep,
)

MIN = (Align.CENTER, Align.CENTER, Align.MIN)


def plate(w, d, t, holes, slots=0, fillet_r=0.0):
    with BuildPart() as p:
        Box(w, d, t, align=MIN)
        if fillet_r:
            fillet(p.edges().filter_by(Axis.Z), fillet_r)
        if holes:
            xs = [(-w / 2 + w * (i + 1) / (holes + 1)) for i in range(holes)]
            with Locations(*[(x, y) for x in xs for y in (-d / 4, d / 4)]):
                Hole(min(w / (holes + 1), d / 2) / 5)
        if slots:
            with BuildSketch(Plane.XY.offset(t)):
                with Locations(*[(0, -d / 2 + d * (i + 1) / (slots + 1)) for i in range(slots)]):
                    SlotCenterToCenter(w / 3, d / (slots + 1) / 3)
            extrude(amount=-t, mode=Mode.SUBTRACT)
    return p.part


def tray(w, d, h, wall, pockets, pocket_depth):
    with BuildPart() as p:
        Box(w, d, h, align=MIN)
        nx, ny = pockets
        pw, pd = (w - wall) / nx - wall, (d - wall) / ny - wall
        with BuildSketch(Plane.XY.offset(h)):
            with Locations(*[(-w / 2 + wall + (pw + wall) * (i + 0.5), -d / 2 + wall + (pd + wall) * (j + 0.5))
                             for i in range(nx) for j in range(ny)]):
                RectangleRounded(pw, pd, min(pw, pd) / 6)  # a milled pocket's corners
        extrude(amount=-pocket_depth, mode=Mode.SUBTRACT)
    return p.part


def open_shell(w, d, h, wall, fillet_r):
    with BuildPart() as p:
        Box(w, d, h, align=MIN)
        if fillet_r:
            fillet(p.edges().filter_by(Axis.Z), fillet_r)
        top = p.faces().sort_by(Axis.Z)[-1]
        offset(amount=-wall, openings=top)
    return p.part


def flange(r_out, r_in, t, bolts, hub_r, hub_h):
    with BuildPart() as p:
        Cylinder(r_out, t, align=MIN)
        Cylinder(hub_r, t + hub_h, align=MIN)
        Cylinder(r_in, t + hub_h, align=MIN, mode=Mode.SUBTRACT)
        with BuildSketch(Plane.XY.offset(t)):
            with PolarLocations((r_out + hub_r) / 2, bolts):
                Circle((r_out - hub_r) / 8)
        extrude(amount=-t, mode=Mode.SUBTRACT)
    return p.part


def bracket(w, leg, t, cham, fil):
    with BuildPart() as p:
        Box(w, leg, t, align=MIN)
        with Locations((0, -leg / 2 + t / 2, 0)):
            Box(w, t, leg, align=MIN)
        if fil:
            inner = p.edges().filter_by(Axis.X).sort_by(Axis.Z)
            fillet(inner.filter_by_position(Axis.Z, t - 1e-6, t + 1e-6).sort_by(Axis.Y)[:1], fil)
        if cham:
            chamfer(p.edges().filter_by(Axis.Z), cham)
        with Locations((w / 4, leg / 6), (-w / 4, leg / 6)):
            Hole(t * 0.6)
    return p.part


def standoffs(w, d, t, n, boss_r, boss_h):
    with BuildPart() as p:
        Box(w, d, t, align=MIN)
        with BuildSketch(Plane.XY.offset(t)):
            with Locations(*[(-w / 2 + w * (i + 0.5) / n, y) for i in range(n) for y in (-d / 4, d / 4)]):
                Circle(boss_r)
        extrude(amount=boss_h)
        with Locations(*[(-w / 2 + w * (i + 0.5) / n, y, t + boss_h) for i in range(n) for y in (-d / 4, d / 4)]):
            Hole(boss_r / 2, depth=boss_h)
    return p.part


def knurled(r, h, grooves, depth):
    with BuildPart() as p:
        Cylinder(r, h, align=MIN)
        with BuildSketch(Plane.XY):
            with PolarLocations(r, grooves):
                RegularPolygon(depth, 3, rotation=180)
        extrude(amount=h, mode=Mode.SUBTRACT)
        fillet(p.edges().filter_by(GeomType.CIRCLE).group_by(Axis.Z)[-1], min(r / 10, h / 10, depth / 3))
    return p.part


def threaded(r, h, pitch, head):
    helix = Helix(pitch, h, r - pitch / 3)
    with BuildPart() as p:
        Cylinder(r - pitch / 2.5, h + pitch, align=MIN)
        with BuildSketch(Plane(origin=helix @ 0, z_dir=helix % 0)):
            RegularPolygon(pitch / 2.2, 3)
        sweep(path=helix, is_frenet=True)
        if head:
            with Locations((0, 0, h + pitch)):
                with BuildSketch():
                    RegularPolygon(r * 1.6, 6)
                extrude(amount=r)
    return p.part


def ribbed(w, d, t, ribs, rib_t, rib_h):
    with BuildPart() as p:
        Box(w, d, t, align=MIN)
        with BuildSketch(Plane.XY.offset(t)):
            with Locations(*[(-w / 2 + w * (i + 0.5) / ribs, 0) for i in range(ribs)]):
                RectangleRounded(rib_t, d * 0.9, rib_t / 2.05)  # rounded rib ends
        extrude(amount=rib_h)
    return p.part


PARTS = {
    "plate-4holes": lambda: plate(80, 60, 6, 2),
    "plate-6holes-thin": lambda: plate(120, 50, 2, 3),
    "plate-slots": lambda: plate(100, 80, 8, 1, slots=2),
    "plate-filleted-10holes": lambda: plate(150, 90, 5, 5, fillet_r=10),
    "plate-slots-filleted": lambda: plate(60, 60, 4, 0, slots=3, fillet_r=6),
    "plate-square-2holes": lambda: plate(40, 40, 10, 1),
    "tray-1pocket": lambda: tray(100, 70, 12, 4, (1, 1), 9),
    "tray-2x2-shallow": lambda: tray(120, 90, 8, 5, (2, 2), 3),
    "tray-3x2": lambda: tray(150, 80, 20, 4, (3, 2), 15),
    "tray-4x4-thin": lambda: tray(100, 100, 6, 2, (4, 4), 4),
    "tray-1x5": lambda: tray(200, 40, 10, 3, (5, 1), 7),
    "shell-box": lambda: open_shell(80, 60, 40, 2, 3),
    "shell-box-filleted": lambda: open_shell(80, 60, 40, 2, 8),
    "shell-tall-thin": lambda: open_shell(40, 40, 100, 1, 5),
    "shell-flat-filleted": lambda: open_shell(150, 100, 20, 3, 15),
    "shell-cup": lambda: open_shell(50, 50, 50, 4, 24),
    "flange-6bolts": lambda: flange(60, 15, 8, 6, 25, 20),
    "flange-8bolts-thin": lambda: flange(100, 40, 4, 8, 50, 10),
    "flange-4bolts": lambda: flange(40, 8, 10, 4, 16, 30),
    "flange-12bolts": lambda: flange(150, 60, 12, 12, 80, 25),
    "flange-3bolts-tall": lambda: flange(30, 6, 6, 3, 12, 60),
    "bracket-plain": lambda: bracket(60, 40, 5, 0, 0),
    "bracket-chamfered": lambda: bracket(60, 40, 5, 2, 0),
    "bracket-filleted": lambda: bracket(80, 50, 6, 0, 10),
    "bracket-both": lambda: bracket(50, 60, 8, 3, 6),
    "bracket-thin": lambda: bracket(100, 30, 2, 0.5, 3),
    "standoffs-2x2": lambda: standoffs(60, 40, 3, 2, 4, 10),
    "standoffs-4x2": lambda: standoffs(120, 60, 4, 4, 5, 15),
    "standoffs-tall": lambda: standoffs(40, 40, 2, 1, 6, 40),
    "standoffs-3x2-small": lambda: standoffs(90, 30, 5, 3, 2, 6),
    "knurled-knob": lambda: knurled(15, 12, 30, 1.5),
    "knurled-fine": lambda: knurled(10, 20, 60, 0.8),
    "knurled-wheel": lambda: knurled(40, 8, 48, 3),
    "knurled-coarse-tall": lambda: knurled(8, 40, 12, 2),
    "threaded-rod": lambda: threaded(5, 12, 1.5, False),
    "threaded-bolt": lambda: threaded(6, 20, 1.25, True),
    "threaded-coarse": lambda: threaded(10, 30, 3, False),
    "threaded-short-bolt": lambda: threaded(4, 8, 0.8, True),
    "ribbed-plate-5": lambda: ribbed(100, 60, 3, 5, 2, 15),
    "ribbed-plate-10-thin": lambda: ribbed(150, 80, 2, 10, 1, 10),
    "ribbed-plate-3-tall": lambda: ribbed(60, 60, 4, 3, 3, 40),
    "ribbed-plate-20": lambda: ribbed(200, 40, 2, 20, 0.8, 6),
    "ribbed-fins-2": lambda: ribbed(40, 100, 5, 2, 4, 25),
    "plate-many-holes": lambda: plate(200, 120, 3, 8),
}


def main():
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    failed = []
    for name, make in PARTS.items():
        try:
            part = make()
            bb = part.bounding_box()
            diag = math.dist((bb.min.X, bb.min.Y, bb.min.Z), (bb.max.X, bb.max.Y, bb.max.Z))
            # As a CAD tool's "fine" STL export: chordal deviation 0.05 % of the part's size.
            tmp = out / f".{name}.stl"
            export_stl(part, str(tmp), tolerance=5e-4 * diag, angular_tolerance=0.2)
            tmp.replace(out / f"{name}.stl")
        except Exception as e:  # a family that OpenCASCADE refuses is named, not hidden
            failed.append(f"{name}: {e}")
    for f in failed:
        print("failed:", f, file=sys.stderr)
    print(f"{len(PARTS) - len(failed)} parts in {out}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
