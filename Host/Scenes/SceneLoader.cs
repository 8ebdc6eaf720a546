using System.Text.Json;

namespace QuantumRayTracing.Scenes;

/// <summary>
/// Reads and validates a scene file. Every problem becomes a <see cref="SceneError"/> naming the file,
/// the element as a JSON path (e.g. <c>rectangles[3].min[0]</c>) and what is wrong with it.
/// </summary>
public static class SceneLoader
{
    public const int MaxRectangles = 4096;
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

            var gridDocument = d.Grid ?? throw Error("grid", "missing");
            var integerBits = Int(gridDocument.IntegerBits, "grid.integerBits", 1, CoordinateGrid.MaxBits);
            var fractionBits = Int(gridDocument.FractionBits ?? 0, "grid.fractionBits", 0, CoordinateGrid.MaxBits - integerBits);
            var grid = new CoordinateGrid(integerBits, fractionBits);

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

            var documents = d.Rectangles ?? throw Error("rectangles", "missing");
            if (documents.Count == 0) throw Error("rectangles", "the scene has no primitives; at least one rectangle is needed");
            if (documents.Count > MaxRectangles) throw Error("rectangles", $"{documents.Count} rectangles; at most {MaxRectangles} are supported");
            var rectangles = documents.Select((r, k) => Rectangle(r, k, grid, materials)).ToArray();
            CameraOffPrimitives(camera.Position, rectangles);

            var areaLights = (d.AreaLights ?? []).Select(AreaLight).ToArray();
            var directionalLights = (d.DirectionalLights ?? []).Select(DirectionalLight).ToArray();

            return new Scene(d.Name ?? Path.GetFileNameWithoutExtension(file), width, height, grid, camera, ambient,
                materials.Values.ToArray(), lights, rectangles)
            {
                AreaLights = areaLights,
                DirectionalLights = directionalLights,
            };
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
        private void CameraOffPrimitives(Vec3 position, Rectangle[] rectangles)
        {
            foreach (var r in rectangles)
            {
                var on = Enumerable.Range(0, 3).All(axis => r.Min[axis] <= position[axis] && position[axis] <= r.Max[axis]);
                if (on)
                    throw Error("camera.position", $"[{position.X}, {position.Y}, {position.Z}] lies on rectangles[{r.Id}] (min [{r.Min.X}, {r.Min.Y}, {r.Min.Z}], max [{r.Max.X}, {r.Max.Y}, {r.Max.Z}]); move the camera off it");
            }
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
