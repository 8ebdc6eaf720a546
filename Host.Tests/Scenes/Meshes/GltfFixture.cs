using System.Buffers.Binary;
using System.Text;
using System.Text.Json.Nodes;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

/// <summary>
/// Writes a small glTF 2.0 file by hand: one mesh of one primitive (float positions, 16-bit indices) that two nodes
/// place: node 0, a root with translation (1, 2, 3) and scale 2, and node 1, its child, with translation (0, 0, 10).
/// A third node carries the mesh too but is in no scene, so it must not be read. As .gltf the buffer is a base64
/// data URI in the JSON; as .glb it is the binary chunk.
/// </summary>
internal static class GltfFixture
{
    public const int Triangles = 4, Lines = 1, TriangleStrip = 5;

    /// <param name="meshless">Nodes without the mesh: a scene with no triangles.</param>
    public static string Write(string path, (float X, float Y, float Z)[] positions, ushort[] indices, int mode = Triangles, bool meshless = false)
    {
        var buffer = new List<byte>();
        foreach (var index in indices) buffer.AddRange(BitConverter.GetBytes(index));
        while (buffer.Count % 4 != 0) buffer.Add(0);
        var positionsOffset = buffer.Count;
        foreach (var (x, y, z) in positions)
            foreach (var value in new[] { x, y, z }) buffer.AddRange(BitConverter.GetBytes(value));
        var bytes = buffer.ToArray();
        var binary = path.EndsWith(".glb", StringComparison.Ordinal);

        var bufferNode = new JsonObject { ["byteLength"] = bytes.Length };
        if (!binary) bufferNode["uri"] = "data:application/octet-stream;base64," + Convert.ToBase64String(bytes);
        JsonArray Bound(bool max) => [
            max ? positions.Max(p => p.X) : positions.Min(p => p.X),
            max ? positions.Max(p => p.Y) : positions.Min(p => p.Y),
            max ? positions.Max(p => p.Z) : positions.Min(p => p.Z)];
        var document = new JsonObject
        {
            ["asset"] = new JsonObject { ["version"] = "2.0" },
            ["scene"] = 0,
            ["scenes"] = new JsonArray(new JsonObject { ["nodes"] = new JsonArray(0) }),
            ["nodes"] = new JsonArray(
                new JsonObject { ["mesh"] = 0, ["translation"] = new JsonArray(1, 2, 3), ["scale"] = new JsonArray(2, 2, 2), ["children"] = new JsonArray(1) },
                new JsonObject { ["mesh"] = 0, ["translation"] = new JsonArray(0, 0, 10) },
                new JsonObject { ["mesh"] = 0, ["translation"] = new JsonArray(100, 100, 100) }),
            ["meshes"] = new JsonArray(new JsonObject
            {
                ["primitives"] = new JsonArray(new JsonObject
                {
                    ["attributes"] = new JsonObject { ["POSITION"] = 1 },
                    ["indices"] = 0,
                    ["mode"] = mode,
                }),
            }),
            ["buffers"] = new JsonArray(bufferNode),
            ["bufferViews"] = new JsonArray(
                new JsonObject { ["buffer"] = 0, ["byteOffset"] = 0, ["byteLength"] = indices.Length * 2, ["target"] = 34963 },
                new JsonObject { ["buffer"] = 0, ["byteOffset"] = positionsOffset, ["byteLength"] = positions.Length * 12, ["target"] = 34962 }),
            ["accessors"] = new JsonArray(
                new JsonObject { ["bufferView"] = 0, ["componentType"] = 5123, ["count"] = indices.Length, ["type"] = "SCALAR" },
                new JsonObject { ["bufferView"] = 1, ["componentType"] = 5126, ["count"] = positions.Length, ["type"] = "VEC3", ["min"] = Bound(false), ["max"] = Bound(true) }),
        };
        // JSON has no infinity or NaN, so a non-finite position goes without the accessor's bounds (optional to a reader).
        if (!positions.All(p => float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z)))
        {
            var accessor = document["accessors"]![1]!.AsObject();
            accessor.Remove("min");
            accessor.Remove("max");
        }
        if (meshless)
            foreach (var node in document["nodes"]!.AsArray()) node!.AsObject().Remove("mesh");
        var json = document.ToJsonString();
        if (!binary)
        {
            File.WriteAllText(path, json);
            return path;
        }
        // GLB: 12-byte header, then a JSON chunk padded with spaces and a BIN chunk padded with zeros, each to 4 bytes.
        var jsonBytes = Encoding.UTF8.GetBytes(json).Concat(Enumerable.Repeat((byte)' ', (4 - Encoding.UTF8.GetByteCount(json) % 4) % 4)).ToArray();
        var binBytes = bytes.Concat(new byte[(4 - bytes.Length % 4) % 4]).ToArray();
        using var file = File.Create(path);
        void Word(uint value)
        {
            Span<byte> word = stackalloc byte[4];
            BinaryPrimitives.WriteUInt32LittleEndian(word, value);
            file.Write(word);
        }
        Word(0x46546C67); // "glTF"
        Word(2);
        Word((uint)(12 + 8 + jsonBytes.Length + 8 + binBytes.Length));
        Word((uint)jsonBytes.Length);
        Word(0x4E4F534A); // "JSON"
        file.Write(jsonBytes);
        Word((uint)binBytes.Length);
        Word(0x004E4942); // "BIN\0"
        file.Write(binBytes);
        return path;
    }
}
