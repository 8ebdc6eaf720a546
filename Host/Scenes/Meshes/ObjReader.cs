using System.Globalization;
using System.Text;

namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// Reads the geometry of a Wavefront OBJ file: <c>v x y z</c> vertex lines and <c>f</c> face lines, nothing else.
/// <list type="bullet">
/// <item>A face of n ≥ 3 corners becomes n − 2 triangles fanned from its first corner: (1, k, k+1) for k = 2..n−1.</item>
/// <item>A corner is <c>v</c>, <c>v/vt</c>, <c>v//vn</c> or <c>v/vt/vn</c>; only the vertex index <c>v</c> is used.
/// Indices start at 1; a negative index counts back from the last vertex read so far (−1 is that vertex).
/// A face may only use vertices defined above it.</item>
/// <item>Numbers after x y z on a <c>v</c> line (a w, or vertex colours) are read past, but must be numbers.</item>
/// <item><c>#</c> starts a comment (to the end of the line); blank lines are skipped.</item>
/// <item>Every other line (<c>vn</c>, <c>vt</c>, <c>usemtl</c>, <c>mtllib</c>, <c>o</c>, <c>g</c>, <c>s</c>, or any
/// keyword this reader does not know) is ignored, and the whole file yields one warning that counts them.</item>
/// </list>
/// Errors (<see cref="MeshError"/>, element <c>line N</c>): a malformed number or index, a non-finite coordinate, an
/// index that is 0 or outside the vertices so far, a face of fewer than 3 corners, no triangles, more than
/// <see cref="TriangleMesh.MaxTriangles"/>.
/// </summary>
public static class ObjReader
{
    public static MeshFile Read(string path)
    {
        FileChecks.ThrowIfNotAFile(path);
        try
        {
            using var reader = new StreamReader(path, Encoding.UTF8, detectEncodingFromByteOrderMarks: true);
            return Parse(reader, path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw FileChecks.Unreadable(path, e);
        }
    }

    /// <summary>Reads OBJ text; <paramref name="file"/> names it in errors and warnings.</summary>
    public static MeshFile Parse(TextReader reader, string file)
    {
        var mesh = new MeshBuilder(file);
        var ignored = new SortedDictionary<string, int>(StringComparer.Ordinal);
        var firstIgnored = 0;
        var corners = new List<int>();
        var number = 0;
        while (reader.ReadLine() is { } line)
        {
            number++;
            var comment = line.IndexOf('#');
            var fields = (comment < 0 ? line : line[..comment]).Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries);
            if (fields.Length == 0) continue;
            var element = $"line {number}";
            switch (fields[0])
            {
                case "v":
                    if (fields.Length < 4)
                        throw new MeshError(file, element, $"a vertex needs three coordinates 'v x y z'; found {fields.Length - 1}");
                    var coordinates = new double[fields.Length - 1];
                    for (var k = 0; k < coordinates.Length; k++) coordinates[k] = Coordinate(fields[k + 1], file, element);
                    mesh.AddVertex(new Vec3(coordinates[0], coordinates[1], coordinates[2]), element);
                    break;
                case "f":
                    if (fields.Length < 4)
                        throw new MeshError(file, element, $"a face needs at least 3 vertices; this one has {fields.Length - 1}");
                    corners.Clear();
                    for (var k = 1; k < fields.Length; k++) corners.Add(VertexIndex(fields[k], mesh.VertexCount, file, element));
                    for (var k = 1; k + 1 < corners.Count; k++) mesh.AddTriangle(corners[0], corners[k], corners[k + 1], element);
                    break;
                default:
                    ignored[fields[0]] = ignored.GetValueOrDefault(fields[0]) + 1;
                    if (firstIgnored == 0) firstIgnored = number;
                    break;
            }
        }
        var built = mesh.Build($"line {Math.Max(number, 1)}");
        string[] warnings = ignored.Count == 0 ? [] :
        [
            $"{file}: ignored {ignored.Values.Sum()} line{(ignored.Values.Sum() == 1 ? "" : "s")} the mesh reader does not use " +
            $"({string.Join(", ", ignored.Select(kv => $"{kv.Key} ×{kv.Value}"))}; the first at line {firstIgnored}): only v and f lines are read",
        ];
        return new MeshFile(file, built, warnings);
    }

    private static double Coordinate(string text, string file, string element)
    {
        if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var value))
        {
            // Writers spell the non-finite values nan, -nan(ind), inf ...: name them as such, not as typos.
            var lower = text.TrimStart('+', '-').ToLowerInvariant();
            throw lower.StartsWith("nan", StringComparison.Ordinal) || lower.StartsWith("inf", StringComparison.Ordinal)
                ? new MeshError(file, element, $"coordinate '{text}' is not finite; every coordinate must be a finite number")
                : new MeshError(file, element, $"'{text}' is not a number");
        }
        // 1e999 parses as infinity; NaN and Infinity parse as themselves.
        if (!double.IsFinite(value)) throw new MeshError(file, element, $"coordinate '{text}' is not finite; every coordinate must be a finite number");
        return value;
    }

    /// <summary>The 0-based vertex index of one face corner (<c>v</c>, <c>v/vt</c>, <c>v//vn</c> or <c>v/vt/vn</c>).</summary>
    private static int VertexIndex(string corner, int vertices, string file, string element)
    {
        var parts = corner.Split('/');
        if (parts.Length > 3 || parts[1..].Any(p => p.Length > 0 && !int.TryParse(p, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out _)))
            throw new MeshError(file, element, $"face corner '{corner}' is not v, v/vt, v//vn or v/vt/vn with whole numbers");
        if (!int.TryParse(parts[0], NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out var index))
            throw new MeshError(file, element, $"face corner '{corner}': '{parts[0]}' is not a vertex index (a whole number)");
        if (index == 0)
            throw new MeshError(file, element, $"face index 0: OBJ indices start at 1 (or count back from -1)");
        var resolved = index > 0 ? index - 1 : vertices + index;
        if (resolved < 0 || resolved >= vertices)
            throw new MeshError(file, element, $"face index {index} is out of range: {vertices} vertices are defined above this line");
        return resolved;
    }
}
