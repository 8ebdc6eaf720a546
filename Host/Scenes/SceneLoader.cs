using System.Globalization;
using System.Text.Json;
using QuantumRayTracing.Scenes.Meshes;

namespace QuantumRayTracing.Scenes;

/// <summary>
/// Reads and validates a scene file. Every problem becomes a <see cref="SceneError"/> naming the file,
/// the element as a JSON path (e.g. <c>rectangles[3].min[0]</c>) and what is wrong with it.
/// </summary>
public static class SceneLoader
{
    public const int MaxRectangles = 4096;

    /// <summary>The most primitives a scene may hold: 2^16, a 16-qubit index register.</summary>
    public const int MaxPrimitives = 65_536;
    public const int MaxImageSide = 8192;

    private static readonly JsonSerializerOptions Json = new()
    {
        PropertyNamingPolicy = JsonNamingPolicy.CamelCase,
        ReadCommentHandling = JsonCommentHandling.Skip,
        AllowTrailingCommas = true,
        // A field given twice is ambiguous (which one did the author mean?): an error, not "the last one wins".
        AllowDuplicateProperties = false,
    };

    public static Scene Load(string path)
    {
        // Reading a directory fails with "access denied", which sends the user looking at permissions.
        if (Directory.Exists(path)) throw new SceneError(path, "file", "is a directory, not a scene file");
        string text;
        try
        {
            text = File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new SceneError(path, "file", e is FileNotFoundException or DirectoryNotFoundException ? "not found" : $"cannot be read ({e.Message})");
        }
        return Parse(text, path);
    }

    /// <summary>Parses scene text; <paramref name="file"/> names it in errors.</summary>
    public static Scene Parse(string text, string file)
    {
        if (string.IsNullOrWhiteSpace(text)) throw new SceneError(file, "$", "the file is empty; a scene is one JSON object");
        SceneDocument? document;
        try
        {
            document = JsonSerializer.Deserialize<SceneDocument>(text, Json);
        }
        catch (JsonException e)
        {
            throw new SceneError(file, Element(e.Path), Describe(e));
        }
        if (document is null) throw new SceneError(file, "$", "the file holds null, not a scene object");
        return new Validator(file).Validate(document);
    }

    private static string Element(string? path) =>
        string.IsNullOrEmpty(path) || path == "$" ? "$" : path.StartsWith("$.") ? path[2..] : path.TrimStart('$');

    private static string Describe(JsonException e)
    {
        var message = e.Message;
        if (message.Contains("could not be mapped", StringComparison.Ordinal))
        {
            var start = message.IndexOf('\'') + 1;
            var end = message.IndexOf('\'', start);
            return end > start ? $"unknown field '{message[start..end]}'" : "unknown field";
        }
        if (message.StartsWith("Duplicate property", StringComparison.Ordinal))
            return "appears twice; give each field once";
        if (e.InnerException is FormatException || message.Contains("could not be converted", StringComparison.Ordinal))
            return $"has the wrong type: expected {Expected(message)}";
        var where = $"is not valid JSON (line {e.LineNumber + 1}, byte {e.BytePositionInLine + 1})";
        // The reader names the first character it rejects; N and I start the NaN and Infinity other writers emit.
        return message.StartsWith("'N' is an invalid start of a value", StringComparison.Ordinal)
            || message.StartsWith("'I' is an invalid start of a value", StringComparison.Ordinal)
            ? $"{where}: JSON has no NaN or Infinity; write a finite number"
            : where;
    }

    // The .NET type named in "could not be converted to T. Path: ...", said in the format's own words.
    private static string Expected(string message)
    {
        const string marker = "converted to ";
        var start = message.IndexOf(marker, StringComparison.Ordinal);
        var end = start < 0 ? -1 : message.IndexOf(". Path:", start, StringComparison.Ordinal);
        var type = end < 0 ? "" : message[(start + marker.Length)..end];
        if (type.EndsWith("[]", StringComparison.Ordinal) || type.Contains("List`1", StringComparison.Ordinal)) return "a list [ ... ]";
        if (type.Contains("Dictionary`2", StringComparison.Ordinal) || type.Contains("Document", StringComparison.Ordinal)) return "an object { ... }";
        if (type.Contains("Int32", StringComparison.Ordinal)) return "a whole number that fits in 32 bits";
        if (type.Contains("Double", StringComparison.Ordinal)) return "a plain JSON number (NaN and Infinity are not numbers in JSON)";
        if (type.Contains("String", StringComparison.Ordinal)) return "a string";
        return "another kind of value (see docs/scenes.md)";
    }

    /// <summary>Checks one document and builds the scene, naming the element of the first problem found.</summary>
    private sealed class Validator(string file)
    {
        private SceneError Error(string element, string problem) => new(file, element, problem);

        public Scene Validate(SceneDocument d)
        {
            var image = d.Image ?? throw Error("image", "missing");
            var width = Int(image.Width, "image.width", 1, MaxImageSide);
            var height = Int(image.Height, "image.height", 1, MaxImageSide);

            var camera = Camera(d.Camera ?? throw Error("camera", "missing"));
            var ambient = Number(d.Ambient ?? 0, "ambient", 0, 1);

            var materials = new Dictionary<string, Material>(StringComparer.Ordinal);
            foreach (var (name, m) in d.Materials ?? [])
            {
                var element = $"materials.{name}";
                if (m is null) throw Error(element, "is null");
                var diffuse = Vector(m.Diffuse, $"{element}.diffuse");
                for (var c = 0; c < 3; c++) Number(diffuse[c], $"{element}.diffuse[{c}]", 0, 1);
                materials[name] = new Material(name, diffuse, Number(m.Mirror ?? 0, $"{element}.mirror", 0, 1));
            }

            var lights = new List<PointLight>();
            foreach (var (l, k) in (d.Lights ?? []).Select((l, k) => (l, k)))
            {
                var element = $"lights[{k}]";
                if (l is null) throw Error(element, "is null");
                var intensity = Vector(l.Intensity, $"{element}.intensity");
                for (var c = 0; c < 3; c++) Number(intensity[c], $"{element}.intensity[{c}]", 0, double.MaxValue);
                lights.Add(new PointLight(Vector(l.Position, $"{element}.position"), intensity));
            }

            var triangles = (d.Triangles ?? []).Select((t, k) => Triangle(t, k, materials)).ToArray();
            var meshes = (d.Meshes ?? []).Select((m, k) => Mesh(m, k, materials)).ToArray();
            var hasTriangles = triangles.Length + meshes.Length > 0;
            var documents = d.Rectangles ?? (hasTriangles ? [] : throw Error("rectangles", "missing"));
            if (documents.Count == 0 && !hasTriangles) throw Error("rectangles", "the scene has no primitives; at least one rectangle, triangle or mesh is needed");
            if (documents.Count > MaxRectangles) throw Error("rectangles", $"{documents.Count} rectangles; at most {MaxRectangles} are supported");
            var total = (long)documents.Count + triangles.Length + meshes.Sum(m => (long)m.Mesh.Triangles.Count);
            if (total > MaxPrimitives) throw Error(hasTriangles ? "meshes" : "rectangles", $"the scene holds {total} primitives; at most {MaxPrimitives} are supported (a 16-qubit index register)");

            var grid = d.Grid is { } gridDocument ? Grid(gridDocument) : hasTriangles ? ChosenGrid(documents, triangles, meshes) : throw Error("grid", "missing");
            var rectangles = documents.Select((r, k) => Rectangle(r, k, grid, materials)).ToArray();
            var (onGrid, quantisation) = hasTriangles ? OnGrid(grid, d.Grid is null, rectangles.Length, triangles, meshes) : ([], null);
            Primitive[] primitives = [.. rectangles, .. onGrid];
            CameraOffPrimitives(camera.Position, primitives);

            var areaLights = (d.AreaLights ?? []).Select(AreaLight).ToArray();
            var directionalLights = (d.DirectionalLights ?? []).Select(DirectionalLight).ToArray();

            return new Scene(d.Name ?? Path.GetFileNameWithoutExtension(file), width, height, grid, camera, ambient,
                materials.Values.ToArray(), lights, primitives)
            {
                AreaLights = areaLights,
                DirectionalLights = directionalLights,
                Quantisation = quantisation,
            };
        }

        private CoordinateGrid Grid(SceneDocument.GridDocument g)
        {
            var integerBits = Int(g.IntegerBits, "grid.integerBits", 1, CoordinateGrid.MaxBits);
            var fractionBits = Int(g.FractionBits ?? 0, "grid.fractionBits", 0, CoordinateGrid.MaxBits - integerBits);
            return new CoordinateGrid(integerBits, fractionBits);
        }

        // A scene's triangles as written: corners and material, each checked, not yet on a grid.
        private sealed record TriangleEntry(string Element, Vec3 A, Vec3 B, Vec3 C, Material Material);

        // A mesh as placed by its transform, zero-area triangles dropped, not yet on a grid.
        private sealed record MeshEntry(string Element, string Path, TriangleMesh Mesh, Material Material, IReadOnlyList<string> Warnings);

        private TriangleEntry Triangle(SceneDocument.TriangleDocument? t, int k, Dictionary<string, Material> materials)
        {
            var element = $"triangles[{k}]";
            if (t is null) throw Error(element, "is null");
            var (a, b, c) = (Vector(t.A, $"{element}.a"), Vector(t.B, $"{element}.b"), Vector(t.C, $"{element}.c"));
            if ((b - a).Cross(c - a) == Vec3.Zero) throw Error(element, "has no area: its corners coincide or lie on one line");
            return new TriangleEntry(element, a, b, c, MaterialOf(t.Material, element, materials));
        }

        private MeshEntry Mesh(SceneDocument.MeshDocument? m, int k, Dictionary<string, Material> materials)
        {
            var element = $"meshes[{k}]";
            if (m is null) throw Error(element, "is null");
            var name = m.File ?? throw Error($"{element}.file", "missing");
            var material = MaterialOf(m.Material, element, materials);
            var transform = new MeshTransform(m.Translate is null ? Vec3.Zero : Vector(m.Translate, $"{element}.translate"),
                Number(m.Scale ?? 1, $"{element}.scale", double.Epsilon, double.MaxValue),
                m.Rotate is null ? Vec3.Zero : Vector(m.Rotate, $"{element}.rotate"));
            // Relative to the scene file, as an image's path in an HTML page is to the page.
            var path = Path.Combine(Path.GetDirectoryName(Path.GetFullPath(file)) ?? "", name);
            try
            {
                var read = MeshReader.Read(path);
                var (mesh, zeroArea) = transform.Apply(read.Mesh).WithoutDegenerate();
                if (mesh.Triangles.Count == 0)
                    throw new MeshError(path, "triangles", zeroArea == 1 ? "the only triangle has zero area" : $"all {zeroArea} triangles have zero area");
                return new MeshEntry(element, path, mesh, material, read.Warnings);
            }
            catch (MeshError e)
            {
                throw Error(element, e.Message);
            }
        }

        // The grid from the primitives where they stand: the largest coordinate and the smallest triangle edge (GridChoice).
        private CoordinateGrid ChosenGrid(IReadOnlyList<SceneDocument.RectangleDocument?> rectangles, TriangleEntry[] triangles, MeshEntry[] meshes)
        {
            var corners = triangles.SelectMany(t => new[] { t.A, t.B, t.C })
                .Concat(meshes.SelectMany(m => m.Mesh.Triangles.SelectMany(t => new[] { m.Mesh.Corner(t, 0), m.Mesh.Corner(t, 1), m.Mesh.Corner(t, 2) })))
                .Concat(rectangles.SelectMany(r => new[] { r?.Min, r?.Max }).OfType<double[]>().Where(v => v.Length == 3).Select(v => new Vec3(v[0], v[1], v[2])));
            var reach = corners.Max(v => Math.Max(v.X, Math.Max(v.Y, v.Z)));
            var edges = triangles.Select(t => Math.Min((t.B - t.A).Length, Math.Min((t.C - t.B).Length, (t.A - t.C).Length)))
                .Concat(meshes.Select(m => m.Mesh.SmallestEdge)).Where(e => e > 0);
            try
            {
                return GridChoice.InPlace(reach, edges.Min(), file).Grid;
            }
            catch (MeshError e)
            {
                throw Error("grid", $"{e.Problem}, or give a grid");
            }
        }

        // The triangles and meshes rounded to the grid, ids after the rectangles', and what the rounding did.
        private (Triangle[] Triangles, TriangleQuantisation Quantisation) OnGrid(CoordinateGrid grid, bool chosen, int first, TriangleEntry[] entries, MeshEntry[] meshes)
        {
            var triangles = new List<Triangle>();
            var (largest, collapsed) = (0.0, 0);
            foreach (var t in entries)
            {
                var corners = new[] { ("a", t.A), ("b", t.B), ("c", t.C) }.Select(c => OnGrid(grid, c.Item2, $"{t.Element}.{c.Item1}")).ToArray();
                largest = Math.Max(largest, Math.Max((corners[0] - t.A).Length, Math.Max((corners[1] - t.B).Length, (corners[2] - t.C).Length)));
                if ((corners[1] - corners[0]).Cross(corners[2] - corners[0]) == Vec3.Zero)
                    throw Error(t.Element, $"collapses to a line or a point on the {grid}: its corners are too close for the grid's step; give a grid with more fraction bits");
                triangles.Add(new Triangle(first + triangles.Count, corners[0], corners[1], corners[2], t.Material));
            }
            foreach (var m in meshes)
            {
                foreach (var t in m.Mesh.Triangles)
                    for (var k = 0; k < 3; k++) OnGrid(grid, m.Mesh.Corner(t, k), m.Element);
                QuantisedMesh quantised;
                try
                {
                    quantised = new GridChoice(grid, Vec3.Zero, 0, m.Mesh.SmallestEdge).Quantise(m.Mesh, m.Path);
                }
                catch (MeshError e)
                {
                    throw Error(m.Element, e.Message);
                }
                (largest, collapsed) = (Math.Max(largest, quantised.LargestDisplacement), collapsed + quantised.Collapsed);
                var (mesh, start) = (quantised.Mesh, first + triangles.Count);
                triangles.AddRange(mesh.Triangles.Select((t, k) => new Triangle(start + k, mesh.Corner(t, 0), mesh.Corner(t, 1), mesh.Corner(t, 2), m.Material)).ToArray());
            }
            return ([.. triangles], new TriangleQuantisation(chosen, largest, collapsed, [.. meshes.SelectMany(m => m.Warnings)]));
        }

        // A corner rounded to the nearest grid value (halves away from zero, as GridChoice rounds), which must lie on the grid.
        private Vec3 OnGrid(CoordinateGrid grid, Vec3 corner, string element)
        {
            var scale = (double)(1 << grid.FractionBits);
            var rounded = new Vec3(Math.Round(corner.X * scale, MidpointRounding.AwayFromZero) / scale,
                Math.Round(corner.Y * scale, MidpointRounding.AwayFromZero) / scale, Math.Round(corner.Z * scale, MidpointRounding.AwayFromZero) / scale);
            for (var axis = 0; axis < 3; axis++)
                if (rounded[axis] < 0 || rounded[axis] > grid.Max)
                    throw Error(element, string.Create(CultureInfo.InvariantCulture,
                        $"corner {corner} lies outside the grid 0..{grid.Max} ({grid}) on axis {axis}; move it (translate) or scale it into the grid"));
            return rounded;
        }

        private Material MaterialOf(string? name, string element, Dictionary<string, Material> materials)
        {
            if (name is null) throw Error($"{element}.material", "missing");
            return materials.TryGetValue(name, out var material) ? material : throw Error($"{element}.material", $"'{name}' is not defined in materials");
        }

        // An emitter, not a primitive: any finite corners (no grid), flat on exactly one axis.
        private AreaLight AreaLight(SceneDocument.AreaLightDocument? a, int k)
        {
            var element = $"areaLights[{k}]";
            if (a is null) throw Error(element, "is null");
            var min = Vector(a.Min, $"{element}.min");
            var max = Vector(a.Max, $"{element}.max");
            for (var axis = 0; axis < 3; axis++)
                if (min[axis] > max[axis])
                    throw Error($"{element}.min[{axis}]", $"{min[axis]} is greater than max[{axis}] = {max[axis]}");
            var flat = Enumerable.Range(0, 3).Where(axis => min[axis] == max[axis]).ToArray();
            if (flat.Length != 1)
                throw Error(element, flat.Length == 0
                    ? "is not a rectangle: min and max differ on every axis (an area light is flat on exactly one axis)"
                    : $"is not a rectangle: min equals max on {flat.Length} axes (an area light is flat on exactly one axis)");
            return new AreaLight(min, max, flat[0], NonNegative(a.Radiance, $"{element}.radiance"));
        }

        private DirectionalLight DirectionalLight(SceneDocument.DirectionalLightDocument? l, int k)
        {
            var element = $"directionalLights[{k}]";
            if (l is null) throw Error(element, "is null");
            var direction = Vector(l.Direction, $"{element}.direction");
            // Scaled by its largest component first, so that neither 1e-200 nor 1e200 under- or overflows the length.
            var largest = Math.Max(Math.Abs(direction.X), Math.Max(Math.Abs(direction.Y), Math.Abs(direction.Z)));
            if (largest == 0) throw Error($"{element}.direction", "is zero; a directional light needs the direction its light travels");
            return new DirectionalLight(new Vec3(direction.X / largest, direction.Y / largest, direction.Z / largest).Normalized(), NonNegative(l.Irradiance, $"{element}.irradiance"));
        }

        private Vec3 NonNegative(double[]? values, string element)
        {
            var v = Vector(values, element);
            for (var c = 0; c < 3; c++)
                if (v[c] < 0) throw Error($"{element}[{c}]", $"{v[c]} is negative; light is at least 0 per channel");
            return v;
        }

        private Camera Camera(SceneDocument.CameraDocument c)
        {
            var position = Vector(c.Position, "camera.position");
            var lookAt = Vector(c.LookAt, "camera.lookAt");
            var up = Vector(c.Up ?? [0, 1, 0], "camera.up");
            var forward = lookAt - position;
            if (forward.Length == 0) throw Error("camera.lookAt", "equals camera.position; the camera has no view direction");
            if (up.Length == 0 || forward.Cross(up).Length <= 1e-9 * forward.Length * up.Length)
                throw Error("camera.up", "is zero or parallel to the view direction");
            var fov = Number(c.VerticalFov ?? 40, "camera.verticalFov", double.Epsilon, 179.999);
            return new Camera(position, lookAt, up, fov);
        }

        // Primitives are flat, so a camera "inside" one lies in its plane within its bounds (edges included):
        // every primary ray would start on the surface, and which side it sees is undefined.
        private void CameraOffPrimitives(Vec3 position, IReadOnlyList<Primitive> primitives)
        {
            foreach (var p in primitives.Where(p => p.Contains(position)))
                throw Error("camera.position", p is Rectangle r
                    ? $"[{position.X}, {position.Y}, {position.Z}] lies on rectangles[{r.Id}] (min [{r.Min.X}, {r.Min.Y}, {r.Min.Z}], max [{r.Max.X}, {r.Max.Y}, {r.Max.Z}]); move the camera off it"
                    : $"[{position.X}, {position.Y}, {position.Z}] lies on triangle {p.Id} (corners {((Triangle)p).A}, {((Triangle)p).B}, {((Triangle)p).C}); move the camera off it");
        }

        private Rectangle Rectangle(SceneDocument.RectangleDocument? r, int id, CoordinateGrid grid, Dictionary<string, Material> materials)
        {
            var element = $"rectangles[{id}]";
            if (r is null) throw Error(element, "is null");
            var min = Vector(r.Min, $"{element}.min");
            var max = Vector(r.Max, $"{element}.max");
            for (var axis = 0; axis < 3; axis++)
            {
                foreach (var (corner, value) in new[] { ("min", min[axis]), ("max", max[axis]) })
                {
                    if (grid.ToFixed(value) is null)
                        throw Error($"{element}.{corner}[{axis}]", value < 0 || value > grid.Max
                            ? $"{value} is outside the grid 0..{grid.Max} ({grid})"
                            : $"{value} is not on the grid ({grid})");
                }
                if (min[axis] > max[axis])
                    throw Error($"{element}.min[{axis}]", $"{min[axis]} is greater than max[{axis}] = {max[axis]}");
            }
            var flat = Enumerable.Range(0, 3).Where(axis => min[axis] == max[axis]).ToArray();
            if (flat.Length != 1)
                throw Error(element, flat.Length == 0
                    ? "is not axis-aligned: min and max differ on every axis (a rectangle is flat on exactly one axis)"
                    : $"is degenerate: min equals max on {flat.Length} axes (a rectangle is flat on exactly one axis)");
            var name = r.Material ?? throw Error($"{element}.material", "missing");
            if (!materials.TryGetValue(name, out var material))
                throw Error($"{element}.material", $"'{name}' is not defined in materials");
            return new Rectangle(id, min, max, flat[0], material);
        }

        private Vec3 Vector(double[]? values, string element)
        {
            if (values is null) throw Error(element, "missing");
            if (values.Length != 3) throw Error(element, $"has {values.Length} numbers; expected 3 ([x, y, z])");
            var v = new Vec3(values[0], values[1], values[2]);
            if (!v.IsFinite) throw Error(element, "holds a value that is not a finite number");
            return v;
        }

        private int Int(int? value, string element, int min, int max)
        {
            if (value is not { } v) throw Error(element, "missing");
            if (v < min || v > max) throw Error(element, $"{v} is outside {min}..{max}");
            return v;
        }

        private double Number(double value, string element, double min, double max)
        {
            if (!double.IsFinite(value)) throw Error(element, "is not a finite number");
            if (value < min || value > max) throw Error(element, $"{value} is outside [{min}, {max}]");
            return value;
        }
    }
}
