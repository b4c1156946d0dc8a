#!/usr/bin/env python3
"""Derives scenes/cornell-box.json, cornell-box.obj and cornell-box.mtl from the published Cornell box data.

Usage: python3 scenes/tools/make_cornell_box.py [path/to/cornell_box.json] [output folder]
Defaults: tests/data/refdata/cornell_box.json in the repository, output scenes/.

What it does (docs/cornell-box.md explains why):
  * geometry in millimetres exactly as published; each polygon is reversed when needed so that it faces the interior
    of the box (walls, floor, ceiling), downwards (light) or outwards (block faces);
  * the ceiling gets the light's rectangular hole, as 4 convex quads around it;
  * the left (red) wall stays the measured non-planar quad: the scene loader splits it into two triangles and warns;
  * colours: spectrum -> CIE 1931 XYZ (equal-energy illuminant, analytic colour matching functions of Wyman, Sloan and
    Shirley 2013) -> linear sRGB, white-balanced so that a flat spectrum maps to grey, clamped to [0, 0.999];
  * the light's relative emission spectrum goes through the same conversion and is scaled so that its luminance
    Y = 0.2126 R + 0.7152 G + 0.0722 B is LIGHT_LUMINANCE W/m^2.
Only the Python standard library is used.
"""
import json
import math
import os
import sys

LIGHT_LUMINANCE = 100.0  # W/m^2, luminance-weighted exitance of the light (an arbitrary but round scale)
XYZ_TO_LINEAR_SRGB = [[3.2406, -1.5372, -0.4986], [-0.9689, 1.8758, 0.0415], [0.0557, -0.2040, 1.0570]]


def lobe(wavelength, mean, sigma_below, sigma_above):
    sigma = sigma_below if wavelength < mean else sigma_above
    return math.exp(-0.5 * ((wavelength - mean) / sigma) ** 2)


def cie1931(wavelength):
    """Multi-lobe fit of the CIE 1931 2-degree colour matching functions (Wyman, Sloan, Shirley, JCGT 2(2), 2013)."""
    x = (1.056 * lobe(wavelength, 599.8, 37.9, 31.0) + 0.362 * lobe(wavelength, 442.0, 16.0, 26.7)
         - 0.065 * lobe(wavelength, 501.1, 20.4, 26.2))
    y = 0.821 * lobe(wavelength, 568.8, 46.9, 40.5) + 0.286 * lobe(wavelength, 530.9, 16.3, 31.1)
    z = 1.217 * lobe(wavelength, 437.0, 11.8, 36.0) + 0.681 * lobe(wavelength, 459.0, 26.0, 13.8)
    return x, y, z


def spectrum_to_linear_rgb(wavelengths, values):
    xyz = [0.0, 0.0, 0.0]
    for w, v in zip(wavelengths, values):
        for i, c in enumerate(cie1931(w)):
            xyz[i] += v * c
    return [sum(m * c for m, c in zip(row, xyz)) for row in XYZ_TO_LINEAR_SRGB]


def white_balanced_rgb(wavelengths, values):
    """Linear sRGB of a spectrum, divided per channel by that of a flat spectrum of 1 (so flat 0.78 -> 0.78 grey)."""
    rgb = spectrum_to_linear_rgb(wavelengths, values)
    white = spectrum_to_linear_rgb(wavelengths, [1.0] * len(wavelengths))
    return [c / w for c, w in zip(rgb, white)]


def interpolate(xs, ys, x):
    for i in range(len(xs) - 1):
        if xs[i] <= x <= xs[i + 1]:
            t = (x - xs[i]) / (xs[i + 1] - xs[i])
            return ys[i] + t * (ys[i + 1] - ys[i])
    raise ValueError(x)


def newell(polygon):
    n = [0.0, 0.0, 0.0]
    for a, b in zip(polygon, polygon[1:] + polygon[:1]):
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return n


def centroid(points):
    return [sum(p[i] for p in points) / len(points) for i in range(3)]


def facing(polygon, direction):
    """The polygon in an order whose normal points along `direction` (reversed if needed)."""
    n = newell(polygon)
    return polygon if sum(a * b for a, b in zip(n, direction)) > 0 else list(reversed(polygon))


def ceiling_pieces(outer, hole):
    """Four convex quads covering the ceiling rectangle minus the light's hole (both axis-aligned in x and z)."""
    y = outer[0][1]
    x0, x1 = min(p[0] for p in outer), max(p[0] for p in outer)
    z0, z1 = min(p[2] for p in outer), max(p[2] for p in outer)
    hx0, hx1 = min(p[0] for p in hole), max(p[0] for p in hole)
    hz0, hz1 = min(p[2] for p in hole), max(p[2] for p in hole)
    rects = [(x0, x1, z0, hz0), (x0, x1, hz1, z1), (x0, hx0, hz0, hz1), (hx1, x1, hz0, hz1)]
    return [[[a, y, c], [b, y, c], [b, y, d], [a, y, d]] for a, b, c, d in rects]


def build(data):
    surfaces = {s["name"]: s for s in data["surfaces"]}
    room = [s for s in data["surfaces"] if not s["name"].startswith(("short_block", "tall_block", "light"))]
    room_centre = centroid([v for s in room for v in s["vertices_mm"]])
    out = []  # (surface name, material, [polygons])
    light = facing(surfaces["light"]["vertices_mm"], [0, -1, 0])
    out.append(("light", "light", [light]))
    for name in ["floor", "ceiling", "back_wall", "left_wall", "right_wall"]:
        polygon = surfaces[name]["vertices_mm"]
        inward = [c - p for c, p in zip(room_centre, centroid(polygon))]
        polygons = ceiling_pieces(polygon, light) if name == "ceiling" else [polygon]
        out.append((name, surfaces[name]["material"], [facing(p, inward) for p in polygons]))
    for block in ["short_block", "tall_block"]:
        faces = [s for s in data["surfaces"] if s["name"].startswith(block + "_")]
        middle = centroid([v for f in faces for v in f["vertices_mm"]])
        oriented = [facing(f["vertices_mm"], [p - m for p, m in zip(centroid(f["vertices_mm"]), middle)])
                    for f in faces]
        out.append((block, "white", oriented))
    return out


def materials(data):
    m = data["materials"]
    wavelengths = m["wavelength_nm"]
    result = {}
    for name in ["white", "red", "green"]:
        result[name] = {"reflectance": [min(max(c, 0.0), 0.999) for c in white_balanced_rgb(wavelengths, m[name])]}
    emission = data["light_emission"]
    spectrum = [interpolate(emission["wavelength_nm"], emission["relative_radiance"], w) for w in wavelengths]
    rgb = [max(c, 0.0) for c in white_balanced_rgb(wavelengths, spectrum)]
    luminance = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
    rho = m["light_reflectance"]["value"]
    result["light"] = {"reflectance": [rho, rho, rho], "emission": [c * LIGHT_LUMINANCE / luminance for c in rgb]}
    return result


def fmt(x):
    text = f"{x:.4f}".rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def vertex(v):
    return "[" + ", ".join(fmt(c) for c in v) + "]"


def camera(data):
    c = data["camera"]
    half_film = c["film_width_height"][1] / 2
    fov = 2 * math.degrees(math.atan(half_film / c["focal_length"]))
    target = [p + 1079.6 * d for p, d in zip(c["position"], c["direction"])]  # the box's mid-depth, z = 279.6
    return c["position"], target, c["up"], fov


def write_json(data, surfaces, mats, path):
    position, target, up, fov = camera(data)
    lines = ["{",
             '  "name": "Cornell box",',
             '  "description": "Cornell Program of Computer Graphics measured box; generated by '
             'scenes/tools/make_cornell_box.py, see docs/cornell-box.md",',
             '  "unit": "mm",',
             f'  "camera": {{"position": {vertex(position)}, "target": {vertex(target)}, "up": {vertex(up)}, '
             f'"fov_y_degrees": {fmt(fov)}}},',
             '  "materials": [']
    entries = []
    for name, m in mats.items():
        text = f'    {{"name": "{name}", "reflectance": {vertex(m["reflectance"])}'
        if "emission" in m:
            text += f', "emission": {vertex(m["emission"])}'
        entries.append(text + "}")
    lines.append(",\n".join(entries))
    lines.append("  ],")
    lines.append('  "surfaces": [')
    entries = []
    for name, material, polygons in surfaces:
        body = ",\n".join("        [" + ", ".join(vertex(v) for v in p) + "]" for p in polygons)
        entries.append(f'    {{"name": "{name}", "material": "{material}", "polygons": [\n{body}\n      ]}}')
    lines.append(",\n".join(entries))
    lines.append("  ]")
    lines.append("}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_obj(data, surfaces, mats, obj_path, mtl_path):
    position, target, up, fov = camera(data)
    header = ["# Cornell box (Cornell Program of Computer Graphics measured data), the same scene as cornell-box.json.",
              "# Generated by scenes/tools/make_cornell_box.py; see docs/cornell-box.md.",
              "# unit: mm",
              "# name: Cornell box",
              "# camera: position " + " ".join(fmt(c) for c in position) + " target " +
              " ".join(fmt(c) for c in target) + " up " + " ".join(fmt(c) for c in up) + " fov_y_degrees " + fmt(fov),
              "mtllib " + os.path.basename(mtl_path)]
    body = []
    count = 0
    for name, material, polygons in surfaces:
        body.append(f"g {name}")
        body.append(f"usemtl {material}")
        for p in polygons:
            body.extend("v " + " ".join(fmt(c) for c in v) for v in p)
            body.append("f " + " ".join(str(count + i + 1) for i in range(len(p))))
            count += len(p)
    with open(obj_path, "w") as f:
        f.write("\n".join(header + body) + "\n")
    mtl = ["# Materials of cornell-box.obj: Kd = reflectance, Ke = emission (W/m^2). See docs/cornell-box.md."]
    for name, m in mats.items():
        mtl += ["", f"newmtl {name}", "Kd " + " ".join(fmt(c) for c in m["reflectance"])]
        if "emission" in m:
            mtl.append("Ke " + " ".join(fmt(c) for c in m["emission"]))
    with open(mtl_path, "w") as f:
        f.write("\n".join(mtl) + "\n")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(os.path.dirname(here))
    source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(repo, "tests", "data", "refdata", "cornell_box.json")
    target = sys.argv[2] if len(sys.argv) > 2 else os.path.join(repo, "scenes")
    with open(source) as f:
        data = json.load(f)
    surfaces = build(data)
    mats = materials(data)
    write_json(data, surfaces, mats, os.path.join(target, "cornell-box.json"))
    write_obj(data, surfaces, mats, os.path.join(target, "cornell-box.obj"), os.path.join(target, "cornell-box.mtl"))
    for name, m in mats.items():
        print(name, "reflectance", [round(c, 4) for c in m["reflectance"]],
              "emission", [round(c, 3) for c in m.get("emission", [0, 0, 0])])


if __name__ == "__main__":
    main()
