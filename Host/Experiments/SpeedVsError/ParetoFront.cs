namespace QuantumRayTracing.Experiments;

/// <summary>The points no other point beats on both axes (lower is better on each), ordered by x.</summary>
public static class ParetoFront
{
    public static IReadOnlyList<int> Of(IReadOnlyList<(double X, double Y)> points)
    {
        var front = new List<int>();
        for (var i = 0; i < points.Count; i++)
        {
            var dominated = false;
            for (var j = 0; j < points.Count && !dominated; j++)
                dominated = j != i && points[j].X <= points[i].X && points[j].Y <= points[i].Y
                    && (points[j].X < points[i].X || points[j].Y < points[i].Y);
            if (!dominated) front.Add(i);
        }
        return [.. front.OrderBy(i => points[i].X).ThenBy(i => points[i].Y)];
    }
}
