using System.Globalization;
using System.Text;

namespace QuantumRayTracing.Scenes.Generation;

/// <summary>
/// Collects materials, lights and rectangles in order and writes them as a scene file in the
/// documented format, one rectangle per line so the files stay readable and diffable. Coordinates
/// lie on a grid of <c>integerBits</c>.<c>fractionBits</c> (fractions only when a scene needs them).
/// </summary>
public sealed class SceneBuilder(string name, int integerBits, int fractionBits = 0)
{
    private readonly List<(string Name, double[] Diffuse, double Mirror)> _materials = [];
    private readonly List<(double[] Position, double[] Intensity)> _lights = [];
    private readonly List<(double[] Min, double[] Max, double[] Radiance)> _areaLights = [];
    private readonly List<(double[] Direction, double[] Irradiance)> _directionalLights = [];
    private double _ambient = 0.1;
    private readonly List<(double[] Min, double[] Max, string Material)> _rectangles = [];
    private (double[] Position, double[] LookAt, double Fov) _camera = ([0, 0, -1], [0, 0, 0], 40);

    public int Count => _rectangles.Count;

    /// <summary>Where the camera stands, so generators can keep rectangles off it.</summary>
    public double[] CameraPosition => _camera.Position;

    public SceneBuilder Material(string material, double r, double g, double b, double mirror = 0)
    {
        _materials.Add((material, [r, g, b], mirror));
        return this;
    }

    public SceneBuilder Light(double x, double y, double z, double intensity)
    {
        _lights.Add(([x, y, z], [intensity, intensity, intensity]));
        return this;
    }

    /// <summary>A rectangular emitter (docs/scenes.md), grey: the same radiance on every channel.</summary>
    public SceneBuilder AreaLight(double[] min, double[] max, double radiance)
    {
        _areaLights.Add((min, max, [radiance, radiance, radiance]));
        return this;
    }

    /// <summary>A light at infinity travelling along <paramref name="direction"/>, grey.</summary>
    public SceneBuilder DirectionalLight(double[] direction, double irradiance)
    {
        _directionalLights.Add((direction, [irradiance, irradiance, irradiance]));
        return this;
    }

    public SceneBuilder Ambient(double ambient)
    {
        _ambient = ambient;
        return this;
    }

    public SceneBuilder Camera(double[] position, double[] lookAt, double verticalFov)
    {
        _camera = (position, lookAt, verticalFov);
        return this;
    }

    /// <summary>A rectangle from corner to corner; exactly one axis must have equal coordinates.</summary>
    public SceneBuilder Rectangle(double[] min, double[] max, string material)
    {
        _rectangles.Add((min, max, material));
        return this;
    }

    /// <summary>The scene file's text, without the generator's marker line.</summary>
    public string ToJson()
    {
        var text = new StringBuilder();
        text.AppendLine("{");
        text.AppendLine($"  \"name\": \"{name}\",");
        text.AppendLine("  \"image\": { \"width\": 128, \"height\": 128 },");
        text.AppendLine($"  \"grid\": {{ \"integerBits\": {integerBits}, \"fractionBits\": {fractionBits} }},");
        text.AppendLine($"  \"camera\": {{ \"position\": {V(_camera.Position)}, \"lookAt\": {V(_camera.LookAt)}, \"up\": [0, 1, 0], \"verticalFov\": {N(_camera.Fov)} }},");
        text.AppendLine($"  \"ambient\": {N(_ambient)},");
        text.AppendLine("  \"materials\": {");
        text.AppendJoin(",\n", _materials.Select(m => $"    \"{m.Name}\": {{ \"diffuse\": {V(m.Diffuse)}, \"mirror\": {N(m.Mirror)} }}")).AppendLine();
        text.AppendLine("  },");
        // Light lists only when the scene has such lights, so older scenes' files stay as they were.
        Section(text, "lights", _lights.Select(l => $"{{ \"position\": {V(l.Position)}, \"intensity\": {V(l.Intensity)} }}"));
        Section(text, "areaLights", _areaLights.Select(l => $"{{ \"min\": {V(l.Min)}, \"max\": {V(l.Max)}, \"radiance\": {V(l.Radiance)} }}"));
        Section(text, "directionalLights", _directionalLights.Select(l => $"{{ \"direction\": {V(l.Direction)}, \"irradiance\": {V(l.Irradiance)} }}"));
        text.AppendLine("  \"rectangles\": [");
        text.AppendJoin(",\n", _rectangles.Select(r => $"    {{ \"min\": {V(r.Min)}, \"max\": {V(r.Max)}, \"material\": \"{r.Material}\" }}")).AppendLine();
        text.AppendLine("  ]");
        text.AppendLine("}");
        return text.ToString();
    }

    private static void Section(StringBuilder text, string name, IEnumerable<string> entries)
    {
        var lines = entries.Select(e => "    " + e).ToArray();
        if (lines.Length == 0) return;
        text.AppendLine($"  \"{name}\": [");
        text.AppendJoin(",\n", lines).AppendLine();
        text.AppendLine("  ],");
    }

    private static string N(double v) => v.ToString(CultureInfo.InvariantCulture);
    private static string V(double[] v) => $"[{string.Join(", ", v.Select(N))}]";
}
