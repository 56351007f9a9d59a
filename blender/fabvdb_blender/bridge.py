# bridge.py — Blender meshes to and from fabvdb meshes: arrays through
# foreach_get/foreach_set (no per-element Python loop), world coordinates,
# scene units turned into millimetres and back, new objects, colour
# attributes and part materials. Main thread only (it touches bpy).
# Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
import bpy
import numpy as np

from . import fabvdb


def mm_per_unit(scene):
    """Millimetres per Blender unit: the scene's unit scale (metres per unit) times 1000."""
    return scene.unit_settings.scale_length * 1000.0


def object_arrays(obj, depsgraph):
    """World-space (n, 3) positions in Blender units, (m, 3) triangles and each triangle's polygon, of the
    evaluated object (modifiers applied)."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        co = np.empty(len(mesh.vertices) * 3, dtype=np.float64)
        mesh.vertices.foreach_get("co", co)
        tris = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int32)
        mesh.loop_triangles.foreach_get("vertices", tris)
        polygon = np.empty(len(mesh.loop_triangles), dtype=np.int32)
        mesh.loop_triangles.foreach_get("polygon_index", polygon)
    finally:
        evaluated.to_mesh_clear()
    matrix = np.array(obj.matrix_world, dtype=np.float64)
    points = co.reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3]
    return points, tris.reshape(-1, 3), polygon


def fabvdb_mesh(obj, context):
    """The object as a fabvdb.Mesh in millimetres (world space)."""
    points, tris, _ = object_arrays(obj, context.evaluated_depsgraph_get())
    return fabvdb.Mesh(points * mm_per_unit(context.scene), tris)


def new_mesh_data(name, vertices_bu, triangles):
    """A Blender mesh from (n, 3) positions in Blender units and (m, 3) triangles."""
    data = bpy.data.meshes.new(name)
    v = np.ascontiguousarray(vertices_bu, dtype=np.float32).ravel()
    t = np.ascontiguousarray(triangles, dtype=np.int32).ravel()
    count = len(t) // 3
    data.vertices.add(len(v) // 3)
    data.vertices.foreach_set("co", v)
    data.loops.add(len(t))
    data.loops.foreach_set("vertex_index", t)
    data.polygons.add(count)
    data.polygons.foreach_set("loop_start", np.arange(0, len(t), 3, dtype=np.int32))
    data.polygons.foreach_set("loop_total", np.full(count, 3, dtype=np.int32))
    data.update(calc_edges=True)
    return data


def new_object(context, name, mesh, collection=None):
    """A new object holding a fabvdb.Mesh (mm) in the scene's units, linked to `collection` (default: the
    active one)."""
    data = new_mesh_data(name, np.asarray(mesh.vertices) / mm_per_unit(context.scene), mesh.triangles)
    obj = bpy.data.objects.new(name, data)
    (collection or context.collection).objects.link(obj)
    return obj


def new_collection(context, name):
    collection = bpy.data.collections.new(name)
    context.scene.collection.children.link(collection)
    return collection


def set_point_colours(obj, name, colours_uint8):
    """A byte colour attribute per vertex from (n, 3) uint8 colours, made active for display."""
    data = obj.data
    attribute = data.color_attributes.new(name, 'BYTE_COLOR', 'POINT')
    rgba = np.ones((len(colours_uint8), 4), dtype=np.float32)
    rgba[:, :3] = np.asarray(colours_uint8, dtype=np.float32) / 255.0
    attribute.data.foreach_set("color", rgba.ravel())
    data.color_attributes.active_color = attribute
    return attribute


def set_point_values(obj, name, values):
    attribute = obj.data.attributes.new(name, 'FLOAT', 'POINT')
    attribute.data.foreach_set("value", np.asarray(values, dtype=np.float32))
    return attribute


def colour_material(name, attribute):
    """A material showing a colour attribute (Material Preview and renders)."""
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    shader = nodes.get("Principled BSDF")
    colour = nodes.new("ShaderNodeVertexColor")
    colour.layer_name = attribute
    material.node_tree.links.new(colour.outputs["Color"], shader.inputs["Base Color"])
    return material


PART_COLOURS = [(0.90, 0.38, 0.30), (0.30, 0.60, 0.90), (0.40, 0.80, 0.40), (0.95, 0.80, 0.30),
                (0.70, 0.45, 0.85), (0.30, 0.80, 0.80), (0.95, 0.55, 0.75), (0.60, 0.60, 0.60)]


def part_material(index):
    """The material of part `index` (made once, shared), coloured in solid view and renders."""
    name = f"fabvdb part {index}"
    material = bpy.data.materials.get(name)
    if material is None:
        material = bpy.data.materials.new(name)
        r, g, b = PART_COLOURS[index % len(PART_COLOURS)]
        shade = 1.0 - 0.15 * (index // len(PART_COLOURS) % 3)
        material.diffuse_color = (r * shade, g * shade, b * shade, 1.0)
        material.use_nodes = True
        material.node_tree.nodes.get("Principled BSDF").inputs["Base Color"].default_value = material.diffuse_color
    return material


def show_parts(obj, labels, part_count):
    """Colours the faces of `obj` by part: a material slot per part and an integer face attribute "part"."""
    data = obj.data
    while len(data.materials) < part_count:
        data.materials.append(part_material(len(data.materials)))
    while len(data.materials) > part_count:
        data.materials.pop()
    labels = np.asarray(labels, dtype=np.int32)
    data.polygons.foreach_set("material_index", labels)
    attribute = data.attributes.get("part") or data.attributes.new("part", 'INT', 'FACE')
    attribute.data.foreach_set("value", labels)
    data.update()


def selected_faces(obj):
    """Indices of the selected faces of `obj` (edit-mode selection included) and their world centres (BU)."""
    if obj.mode == 'EDIT':
        obj.update_from_editmode()
    data = obj.data
    select = np.empty(len(data.polygons), dtype=bool)
    data.polygons.foreach_get("select", select)
    centres = np.empty(len(data.polygons) * 3, dtype=np.float64)
    data.polygons.foreach_get("center", centres)
    matrix = np.array(obj.matrix_world, dtype=np.float64)
    centres = centres.reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3]
    index = np.flatnonzero(select)
    return index, centres[index]


def annotation_path(context):
    """The points (BU) of the last annotation stroke drawn in the scene, or None."""
    notes = context.scene.grease_pencil
    if notes is None or not notes.layers:
        return None
    layer = notes.layers.active or notes.layers[-1]
    frame = layer.active_frame or (layer.frames[-1] if layer.frames else None)
    if frame is None or not frame.strokes:
        return None
    stroke = frame.strokes[-1]
    points = np.empty(len(stroke.points) * 3, dtype=np.float64)
    stroke.points.foreach_get("co", points)
    return points.reshape(-1, 3)
