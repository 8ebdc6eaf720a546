using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// Stratified jittered points on an area light: <c>count</c> samples split the rectangle into the
/// cells of <see cref="Strata.Split"/>, the more numerous along the longer side; sample s lies in its
/// cell at a uniform position drawn from its own stream (two numbers: along the first in-plane axis, then the second).
/// </summary>
public static class AreaLightSampler
{
    /// <summary>Cells along the light's first and second in-plane axes.</summary>
    public static (int AlongU, int AlongV) Cells(AreaLight light, int count)
    {
        var (columns, rows) = Strata.Split(count);
        var (u, v) = light.PlaneAxes;
        return light.Max[u] - light.Min[u] >= light.Max[v] - light.Min[v] ? (columns, rows) : (rows, columns);
    }

    /// <summary>Sample <paramref name="sample"/> of <paramref name="count"/>, jittered by two numbers of <paramref name="random"/>.</summary>
    public static Vec3 Sample(AreaLight light, int sample, int count, SeededRandom random)
    {
        var (alongU, alongV) = Cells(light, count);
        var ju = random.NextDouble();
        var jv = random.NextDouble();
        var (u, v) = Strata.Point(sample, alongU, alongV, ju, jv);
        return light.PointAt(u, v);
    }
}
