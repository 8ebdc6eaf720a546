namespace QuantumRayTracing.Output.Plots;

/// <summary>The filled shape drawn at each point of a series with markers.</summary>
public enum MarkerShape
{
    /// <summary>A disc.</summary>
    Circle,

    /// <summary>An axis-aligned square.</summary>
    Square,

    /// <summary>A square standing on one corner.</summary>
    Diamond,

    /// <summary>A triangle pointing up.</summary>
    TriangleUp,

    /// <summary>A triangle pointing down.</summary>
    TriangleDown,

    /// <summary>A thick upright cross.</summary>
    Plus,

    /// <summary>A thick diagonal cross.</summary>
    Cross,
}

/// <summary>The geometry of each <see cref="MarkerShape"/>.</summary>
internal static class MarkerGeometry
{
    /// <summary>
    /// Whether the offset (<paramref name="dx"/>, <paramref name="dy"/>) from the marker centre (y down) lies in the
    /// shape of nominal radius <paramref name="r"/>. Sizes are tuned so the shapes look equally heavy, and every
    /// shape covers at least a disc of radius r / 3 around its centre, so the centre pixel is always solid.
    /// </summary>
    public static bool Contains(this MarkerShape shape, double dx, double dy, double r) => shape switch
    {
        MarkerShape.Circle => dx * dx + dy * dy <= r * r,
        MarkerShape.Square => Math.Abs(dx) <= 0.82 * r && Math.Abs(dy) <= 0.82 * r,
        MarkerShape.Diamond => Math.Abs(dx) + Math.Abs(dy) <= 1.2 * r,
        MarkerShape.TriangleUp => InTriangle(dx, dy, r),
        MarkerShape.TriangleDown => InTriangle(dx, -dy, r),
        MarkerShape.Plus => InPlus(dx, dy, 1.25 * r),
        // The plus turned by 45 degrees. Thin shapes get longer arms to look as heavy as the filled ones.
        MarkerShape.Cross => InPlus((dx + dy) * Math.Sqrt(0.5), (dx - dy) * Math.Sqrt(0.5), 1.3 * r),
        _ => false,
    };

    // Apex above the centre, base below it; the centroid sits near the centre so the point looks centred.
    private static bool InTriangle(double dx, double dy, double r)
    {
        double apex = -1.2 * r, baseline = 0.8 * r, halfBase = 1.15 * r;
        return dy >= apex && dy <= baseline && Math.Abs(dx) <= halfBase * (dy - apex) / (baseline - apex);
    }

    private static bool InPlus(double dx, double dy, double r)
    {
        var half = 0.3 * r;
        return (Math.Abs(dx) <= half && Math.Abs(dy) <= r) || (Math.Abs(dy) <= half && Math.Abs(dx) <= r);
    }
}
