using System.Globalization;

namespace QuantumRayTracing.Scenes;

/// <summary>
/// How a scene's triangles reached its grid: whether the grid was chosen from the scene (its reach and smallest
/// triangle edge) or given in the file, the largest distance a vertex moved when rounded to it, how many mesh triangles
/// collapsed there and were dropped, and the mesh readers' warnings.
/// </summary>
public sealed record TriangleQuantisation(bool GridChosen, double LargestDisplacement, int Collapsed, IReadOnlyList<string> Warnings)
{
    /// <summary>One line for what a render or a check prints: where the grid came from, the displacement in world units and grid steps, the dropped triangles.</summary>
    public string Describe(CoordinateGrid grid) => string.Create(CultureInfo.InvariantCulture,
        $"{(GridChosen ? "grid chosen from the scene's extent and smallest triangle edge" : "grid from the scene file")}; " +
        $"largest vertex displacement {LargestDisplacement:G4} ({LargestDisplacement / grid.Step:0.###} steps)" +
        $"{(Collapsed > 0 ? $"; {Collapsed} mesh triangles collapsed on the grid and were dropped" : "")}");
}
