"""The Cycles anchor: book 2's Cornell box (--scene ch11) and Cornell smoke (--scene ch12) built in
Blender from the same numbers as chapters/ch11_instances/cornell_box.h and
chapters/ch12_volumes/cornell_smoke.h, rendered by Cycles on the CPU with every setting that
would make its image differ from ours turned to ours, and written as a linear OpenEXR file.

  blender -b --factory-startup -noaudio -P bench/cycles_anchor.py -- \
      --scene ch11 --width 200 --spp 32 --seed 1 --threads 2 --out X.exr --stats-out X.json

Blender is only a yardstick here, as Embree is for the traversal: tools/convergence --cycles
runs this script (tools/install-deps --anchors installs Debian's blender) and nothing in the
build or the tests needs it.

What had to be matched, and how (Blender 3.4's defaults in brackets):
- Geometry: every quad and box face as a mesh with its world-space corners, the boxes turned
  about y and moved as rt::rotate and rt::translate do (x' = x cos a + z sin a,
  z' = -x sin a + z cos a), so no Blender axis or rotation convention is involved. The scene's
  units are kept (the room is 555 wide): light and diffuse transport do not depend on scale,
  and the media's densities are per unit of length, as ours.
- Camera: at (278, 278, -800) looking at (278, 278, 0) with y up, a vertical field of view of
  40 degrees, a pinhole (no depth of field). Blender's camera looks along its local -z with
  local y up, so a half turn about y points it along +z with y up, and the image's right is -x,
  as ours (the green wall at x = 555 on the left).
- Materials: Lambertian walls as Diffuse BSDF of roughness 0 with the albedo as its linear
  colour; the lamp as an Emission shader of strength 1 with the radiance (15 or 7) as its
  colour (a mesh's emission of strength 1 is seen as its colour: radiance, not power). Cycles
  emits from both sides of a mesh, as book 2's diffuse_light does.
- Media: the boxes' material has no surface, only a volume: the white fog (albedo 1) a Volume
  Scatter of density 0.01, isotropic (anisotropy 0); the black smoke (albedo 0) a pure absorber,
  Volume Absorption of density 0.01 (its absorption coefficient is density x (1 - colour), so
  colour black). Marked homogeneous, so Cycles samples distances in them analytically.
- World: black, strength 0 (the book's background is black).
- Bounces: every kind up to 50, as the scene's max_depth [12 in all; diffuse 4, glossy 4,
  transmission 12, volume 0, transparent 8]. Cycles ends longer paths by Russian roulette, which
  keeps the mean.
- No bias: light threshold 0 [0.01], clamping off [direct 0, indirect 10], filter glossy 0 [1],
  adaptive sampling off [on], denoising off [off in 3.4's factory settings].
- The film: a box filter 1 pixel wide [Blackman-Harris, 1.5 pixels], so each pixel averages
  samples inside its own square, as ours; exposure 0, the "Standard" view transform [Filmic] and
  no look (they only change what a screen shows, but are set so that a saved PNG would match),
  and the EXR written as 32-bit linear floats, uncompressed.
- Seed: Cycles' seed [0], not animated; Cycles' own sampling pattern is kept (progressive
  multi-jitter in 3.4) and stated.
- Threads: the given count, fixed [all cores].

The stats file is JSON: render_seconds (bpy.ops.render.render, which includes Cycles' scene
export and BVH build, the counterpart of our scene building), the settings used and Blender's
version. A bad argument: one line on stderr, exit code 2."""
import argparse
import json
import math
import sys
import time

import bpy

ROOM = 555.0
WHITE, RED, GREEN = (0.73, 0.73, 0.73), (0.65, 0.05, 0.05), (0.12, 0.45, 0.15)
# (Q, u, v, radiance) of each scene's lamp, and its boxes: (size, degrees about y, offset).
LAMPS = {"ch11": ((343, 554, 332), (-130, 0, 0), (0, 0, -105), 15.0),
         "ch12": ((113, 554, 127), (330, 0, 0), (0, 0, 305), 7.0)}
BOXES = [((165, 330, 165), 15.0, (265, 0, 295)), ((165, 165, 165), -18.0, (130, 0, 65))]
LIFT = 0.01  # the media's boxes above the floor (of a 555-unit room), see build()


def fail(message):
    print(f"cycles_anchor: error: {message}", file=sys.stderr)
    sys.exit(2)


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def quad_corners(Q, u, v):
    return [Q, add(Q, u), add(add(Q, u), v), add(Q, v)]


def mesh_object(name, faces, material):
    """One object whose faces are lists of world-space corners (no object transform)."""
    vertices, indices = [], []
    for face in faces:
        indices.append(list(range(len(vertices), len(vertices) + len(face))))
        vertices.extend(face)
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, [], indices)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    obj.data.materials.append(material)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def box_faces(size, degrees, offset):
    """The six faces of the box (0,0,0)-size turned about y by degrees and moved by offset."""
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)

    def place(p):
        x, y, z = p
        return (c * x + s * z + offset[0], y + offset[1], -s * x + c * z + offset[2])

    sx, sy, sz = size
    corner = [(x, y, z) for x in (0, sx) for y in (0, sy) for z in (0, sz)]
    # Corners indexed by bits (x, y, z); each face's four corners in order around it.
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return [[place(corner[i]) for i in face] for face in faces]


def material(name, surface=None, volume=None):
    """A node material: `surface` and `volume` are (node type, {input: value}) or None."""
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    for socket, spec in (("Surface", surface), ("Volume", volume)):
        if spec is None:
            continue
        node = nodes.new(spec[0])
        for key, value in spec[1].items():
            node.inputs[key].default_value = value
        links.new(node.outputs[0], output.inputs[socket])
    m.cycles.homogeneous_volume = volume is not None
    return m


def diffuse(name, albedo):
    return material(name, ("ShaderNodeBsdfDiffuse", {"Color": (*albedo, 1), "Roughness": 0.0}))


def build(scene_name):
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    white, red, green = diffuse("white", WHITE), diffuse("red", RED), diffuse("green", GREEN)
    Q, u, v, radiance = LAMPS[scene_name]
    lamp = material("lamp", ("ShaderNodeEmission",
                             {"Color": (radiance, radiance, radiance, 1), "Strength": 1.0}))
    mesh_object("green wall", [quad_corners((ROOM, 0, 0), (0, ROOM, 0), (0, 0, ROOM))], green)
    mesh_object("red wall", [quad_corners((0, 0, 0), (0, ROOM, 0), (0, 0, ROOM))], red)
    mesh_object("lamp", [quad_corners(Q, u, v)], lamp)
    mesh_object("white walls", [quad_corners((0, 0, 0), (ROOM, 0, 0), (0, 0, ROOM)),
                                quad_corners((ROOM, ROOM, ROOM), (-ROOM, 0, 0), (0, 0, -ROOM)),
                                quad_corners((0, 0, ROOM), (ROOM, 0, 0), (0, ROOM, 0))], white)
    if scene_name == "ch11":
        for k, (size, degrees, offset) in enumerate(BOXES):
            mesh_object(f"box {k}", box_faces(size, degrees, offset), white)
    else:
        smoke = material("black smoke", volume=("ShaderNodeVolumeAbsorption",
                                                {"Color": (0, 0, 0, 1), "Density": 0.01}))
        fog = material("white fog", volume=("ShaderNodeVolumeScatter",
                                            {"Color": (1, 1, 1, 1), "Density": 0.01,
                                             "Anisotropy": 0.0}))
        for (size, degrees, offset), m in zip(BOXES, (smoke, fog)):
            # The media's bottoms lie in the floor's plane. Cycles, meeting two faces at one
            # distance, crosses the floor's face as well and loses the light that the fog scatters
            # onto the floor there (2-4 % darker blocks where the fog meets the floor); lifted by
            # LIFT, each ray meets them in the book's order.
            mesh_object(m.name, box_faces(size, degrees, add(offset, (0, LIFT, 0))), m)

    camera = bpy.data.cameras.new("camera")
    camera.type = "PERSP"
    camera.sensor_fit = "VERTICAL"
    camera.angle_y = math.radians(40)
    camera.dof.use_dof = False
    camera.clip_start, camera.clip_end = 0.001, 1e5
    obj = bpy.data.objects.new("camera", camera)
    obj.location = (278, 278, -800)
    obj.rotation_euler = (0.0, math.pi, 0.0)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj

    world = bpy.context.scene.world or bpy.data.worlds.new("world")
    bpy.context.scene.world = world
    world.use_nodes = True
    background = world.node_tree.nodes.get("Background")
    background.inputs["Color"].default_value = (0, 0, 0, 1)
    background.inputs["Strength"].default_value = 0.0


def configure(args):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.spp
    c.seed = args.seed
    c.use_animated_seed = False
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.blur_glossy = 0.0
    for bounces in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
                    "volume_bounces", "transparent_max_bounces"):
        setattr(c, bounces, 50)
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    r = scene.render
    r.resolution_x = r.resolution_y = args.width
    r.resolution_percentage = 100
    r.film_transparent = False
    r.threads_mode = "FIXED"
    r.threads = args.threads
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = r.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.exr_codec = "NONE"
    return {"samples": c.samples, "seed": c.seed, "sampling_pattern": c.sampling_pattern,
            "adaptive_sampling": c.use_adaptive_sampling, "denoising": c.use_denoising,
            "clamp_direct": c.sample_clamp_direct, "clamp_indirect": c.sample_clamp_indirect,
            "light_threshold": c.light_sampling_threshold, "filter": c.pixel_filter_type,
            "filter_width": c.filter_width, "max_bounces": c.max_bounces,
            "view_transform": scene.view_settings.view_transform, "threads": r.threads,
            "width": r.resolution_x, "height": r.resolution_y}


def parse(argv):
    parser = argparse.ArgumentParser(prog="cycles_anchor.py")
    parser.add_argument("--scene", required=True, choices=sorted(LAMPS))
    parser.add_argument("--width", type=int, default=200)
    parser.add_argument("--spp", type=int, required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--out", required=True, help="the image, an .exr file")
    parser.add_argument("--stats-out", required=True)
    parser.error = fail
    args = parser.parse_args(argv)
    for option, value in (("--width", args.width), ("--spp", args.spp),
                          ("--threads", args.threads)):
        if value < 1:
            fail(f"{option} must be at least 1, got {value}")
    if args.seed < 0:
        fail(f"--seed must be at least 0, got {args.seed}")
    return args


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse(argv)
    build(args.scene)
    settings = configure(args)
    start = time.perf_counter()
    bpy.ops.render.render(write_still=False)
    seconds = time.perf_counter() - start
    bpy.data.images["Render Result"].save_render(args.out)
    with open(args.stats_out, "w") as f:
        json.dump({"render_seconds": seconds, "settings": settings, "scene": args.scene,
                   "blender": bpy.app.version_string}, f, indent=1)
        f.write("\n")


main()
