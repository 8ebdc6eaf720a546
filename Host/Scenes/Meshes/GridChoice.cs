using System.Globalization;

namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// The fixed-point <see cref="CoordinateGrid"/> a mesh's triangles are put on, and where the mesh goes on it.
/// <list type="number">
/// <item><b>Placement.</b> The mesh is moved by <see cref="Offset"/> = −(its bounds' minimum corner), so that corner
/// lands on the origin and every coordinate lies in 0..E, E = <see cref="Extent"/>, the largest side of the bounds.</item>
/// <item><b>Integer bits.</b> I = the smallest I ≥ 1 with 2^I − 1 ≥ E: the grid's integer part reaches E. Since
/// (2^I − 1)·2^F is a whole number of steps at or above E·2^F, rounding to the nearest step never leaves the grid.
/// A mesh that would need I &gt; <see cref="CoordinateGrid.MaxBits"/> is an error (scale it down).</item>
/// <item><b>Fraction bits.</b> F = the smallest F ≥ 0 with e·2^F ≥ <see cref="StepsPerSmallestEdge"/> (4), e the
/// mesh's smallest non-zero edge: the shortest edge spans at least 4 grid steps, so rounding each end by at most
/// half a step changes it by at most a quarter of its length.</item>
/// <item><b>Cap.</b> I + F ≤ <see cref="CoordinateGrid.MaxBits"/>: F is cut to MaxBits − I when it would pass that;
/// short edges then span fewer steps, and triangles that collapse are dropped by <see cref="Quantise"/>.</item>
/// </list>
/// </summary>
public sealed record GridChoice(CoordinateGrid Grid, Vec3 Offset, double Extent, double SmallestEdge)
{
    /// <summary>How many grid steps the smallest edge should span at least (unless the 16-bit cap prevents it).</summary>
    public const int StepsPerSmallestEdge = 4;

    /// <summary>Whether the cap cut the fraction bits below what the smallest edge asks for.</summary>
    public bool Capped => SmallestEdge * (1 << Grid.FractionBits) < StepsPerSmallestEdge;

    /// <summary>How many grid steps the smallest edge spans.</summary>
    public double StepsOnSmallestEdge => SmallestEdge / Grid.Step;

    /// <summary>The grid for <paramref name="mesh"/> by the rule above; <paramref name="file"/> names it in errors.</summary>
    public static GridChoice For(TriangleMesh mesh, string file)
    {
        var (min, _) = mesh.Bounds;
        // Zero minus the corner, not its negation: a corner at 0 gives an offset of 0, not −0.
        return Choose(mesh.Extent, mesh.SmallestEdge, Vec3.Zero - min, file, "bounds", "the mesh spans");
    }

    /// <summary>
    /// The grid for a scene's primitives where they stand (no placement, <see cref="Offset"/> zero): the integer bits reach
    /// <paramref name="reach"/>, the largest coordinate of any primitive, and the fraction bits follow
    /// <paramref name="smallestEdge"/>, the smallest triangle edge, by the rule above. <paramref name="file"/> names the scene in errors.
    /// </summary>
    public static GridChoice InPlace(double reach, double smallestEdge, string file) =>
        Choose(reach, smallestEdge, Vec3.Zero, file, "grid", "the scene reaches");

    private static GridChoice Choose(double extent, double smallestEdge, Vec3 offset, string file, string element, string reaches)
    {
        var integerBits = 1;
        while (integerBits <= CoordinateGrid.MaxBits && Math.Pow(2, integerBits) - 1 < extent) integerBits++;
        if (integerBits > CoordinateGrid.MaxBits)
            throw new MeshError(file, element, string.Create(CultureInfo.InvariantCulture,
                $"{reaches} {extent:G6} units; a {CoordinateGrid.MaxBits}-bit grid reaches {(1 << CoordinateGrid.MaxBits) - 1}: scale it down"));
        var fractionBits = 0;
        while (fractionBits < CoordinateGrid.MaxBits - integerBits && smallestEdge * Math.Pow(2, fractionBits) < StepsPerSmallestEdge) fractionBits++;
        return new GridChoice(new CoordinateGrid(integerBits, fractionBits), offset, extent, smallestEdge);
    }

    /// <summary>
    /// <paramref name="mesh"/> moved by <see cref="Offset"/> and each coordinate rounded to the nearest grid value
    /// (halves away from zero); triangles that lose their area on the grid are dropped and counted. Every triangle
    /// collapsing is an error: the grid is too coarse for the mesh.
    /// </summary>
    public QuantisedMesh Quantise(TriangleMesh mesh, string file)
    {
        var scale = (double)(1 << Grid.FractionBits);
        var largest = 0.0;
        var used = new bool[mesh.Vertices.Count];
        foreach (var t in mesh.Triangles)
            for (var k = 0; k < 3; k++) used[t[k]] = true;
        var vertices = new Vec3[mesh.Vertices.Count];
        for (var i = 0; i < vertices.Length; i++)
        {
            var placed = mesh.Vertices[i] + Offset;
            var onGrid = new Vec3(Round(placed.X, scale), Round(placed.Y, scale), Round(placed.Z, scale));
            vertices[i] = onGrid;
            if (used[i]) largest = Math.Max(largest, (onGrid - placed).Length);
        }
        var (kept, collapsed) = new TriangleMesh(vertices, mesh.Triangles).WithoutDegenerate();
        if (kept.Triangles.Count == 0)
            throw new MeshError(file, "grid", $"{(mesh.Triangles.Count == 1 ? "the only triangle collapses" : $"all {mesh.Triangles.Count} triangles collapse")} on the {Grid}: the triangles are too small beside the mesh's extent");
        return new QuantisedMesh(kept, collapsed, largest);
    }

    private static double Round(double value, double scale) => Math.Round(value * scale, MidpointRounding.AwayFromZero) / scale;
}
