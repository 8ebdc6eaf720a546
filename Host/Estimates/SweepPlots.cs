using QuantumRayTracing.Output;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The PNG plots of a resource sweep. They are drawn by <c>SweepPlots.Draw.cs</c> with the plot writer
/// of <c>Output/Plots</c> (LinePlot), which Host.csproj compiles only when that writer is part of the
/// build; without it a sweep writes its tables and no plots.
/// </summary>
public static partial class SweepPlots
{
    /// <summary>One plot: the file name's suffix (estimates-&lt;suffix&gt;.png beside the report), its caption and image.</summary>
    public sealed record Plot(string Suffix, string Caption, RgbImage Image);

    public static IReadOnlyList<Plot> Draw(SweepReport report, IReadOnlyList<int> primitives, IReadOnlyList<int> bits)
    {
        var plots = new List<Plot>();
        DrawAll(report, primitives, bits, plots);
        return plots;
    }

    static partial void DrawAll(SweepReport report, IReadOnlyList<int> primitives, IReadOnlyList<int> bits, List<Plot> plots);
}
