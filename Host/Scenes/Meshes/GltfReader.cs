using System.Numerics;
using SharpGLTF.Schema2;

namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// Reads the triangles of a glTF 2.0 file (<c>.gltf</c> with its buffers embedded or beside it, or binary <c>.glb</c>)
/// through SharpGLTF: every primitive of every mesh that a node of the default scene (scene 0 when none is named)
/// or any of its descendants carries, with that node's world transform applied to its POSITION values. A mesh
/// used by two nodes counts twice. Primitives in mode TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN are read (strips and
/// fans as SharpGLTF splits them into triangles); POINTS and the LINE modes are errors. Materials, normals,
/// texture coordinates, skins, morph targets and animations are not read.
/// Errors (<see cref="MeshError"/>): a file SharpGLTF refuses, a primitive that is not triangles or has no POSITION,
/// a non-finite position, no triangles, more than <see cref="TriangleMesh.MaxTriangles"/>.
/// </summary>
public static class GltfReader
{
    public static MeshFile Read(string path)
    {
        FileChecks.ThrowIfNotAFile(path);
        ModelRoot model;
        try
        {
            model = ModelRoot.Load(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw FileChecks.Unreadable(path, e);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // SharpGLTF's checks refuse a non-finite POSITION before we see it: say so as for any other mesh format.
            if (FirstNonFinitePosition(path) is var (element, vertex)) throw new MeshError(path, element, MeshBuilder.NotFinite(vertex));
            // Its schema, link and data checks, and the JSON or GLB container's own errors.
            throw new MeshError(path, "file", $"is not a glTF 2.0 file that can be read: {FileChecks.FirstLine(e.Message)}");
        }
        var scene = model.DefaultScene ?? throw new MeshError(path, "scenes", "the file has no scene, so no node places a mesh");
        var mesh = new MeshBuilder(path);
        foreach (var root in scene.VisualChildren) AddNode(root, mesh, path);
        return new MeshFile(path, mesh.Build($"scenes[{scene.LogicalIndex}]"), []);
    }

    /// <summary>
    /// The first NaN or infinite POSITION value of any primitive (untransformed), read without SharpGLTF's checks;
    /// null when there is none or the file cannot be read even so.
    /// </summary>
    private static (string Element, Vec3 Vertex)? FirstNonFinitePosition(string path)
    {
        try
        {
            var model = ModelRoot.Load(path, new ReadSettings { Validation = SharpGLTF.Validation.ValidationMode.Skip });
            foreach (var mesh in model.LogicalMeshes)
                foreach (var primitive in mesh.Primitives)
                {
                    if (primitive.GetVertexAccessor("POSITION") is not { } positions) continue;
                    var values = positions.AsVector3Array();
                    for (var i = 0; i < values.Count; i++)
                        if (!float.IsFinite(values[i].X) || !float.IsFinite(values[i].Y) || !float.IsFinite(values[i].Z))
                            return ($"meshes[{mesh.LogicalIndex}].primitives[{primitive.LogicalIndex}].POSITION[{i}]", new Vec3(values[i].X, values[i].Y, values[i].Z));
                }
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
        }
        return null;
    }

    private static void AddNode(Node node, MeshBuilder mesh, string path)
    {
        if (node.Mesh is { } nodeMesh)
        {
            var world = node.WorldMatrix;
            foreach (var primitive in nodeMesh.Primitives)
                AddPrimitive(primitive, world, mesh, path, $"meshes[{nodeMesh.LogicalIndex}].primitives[{primitive.LogicalIndex}]");
        }
        foreach (var child in node.VisualChildren) AddNode(child, mesh, path);
    }

    private static void AddPrimitive(MeshPrimitive primitive, Matrix4x4 world, MeshBuilder mesh, string path, string element)
    {
        var mode = primitive.DrawPrimitiveType;
        if (mode is not (PrimitiveType.TRIANGLES or PrimitiveType.TRIANGLE_STRIP or PrimitiveType.TRIANGLE_FAN))
            throw new MeshError(path, element, $"mode {mode} ({(int)mode}): only triangles are read (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN)");
        var positions = primitive.GetVertexAccessor("POSITION")
            ?? throw new MeshError(path, element, "has no POSITION attribute");
        var first = mesh.VertexCount;
        var values = positions.AsVector3Array();
        for (var i = 0; i < values.Count; i++)
        {
            var p = Vector3.Transform(values[i], world);
            mesh.AddVertex(new Vec3(p.X, p.Y, p.Z), $"{element}.POSITION[{i}]");
        }
        foreach (var (a, b, c) in primitive.GetTriangleIndices())
        {
            if (Math.Max(a, Math.Max(b, c)) >= values.Count || Math.Min(a, Math.Min(b, c)) < 0)
                throw new MeshError(path, element, $"triangle ({a}, {b}, {c}) uses a vertex outside 0..{values.Count - 1}");
            mesh.AddTriangle(first + a, first + b, first + c, element);
        }
    }
}
