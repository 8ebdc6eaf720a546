using System.Globalization;

namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// What <c>qrt scenes check</c> says of a mesh file: read it, drop its zero-area triangles, choose its grid
/// (<see cref="GridChoice"/>), put it there, and summarise all of it on one line.
/// </summary>
public static class MeshCheck
{
    public sealed record Result(MeshFile File, int ZeroArea, GridChoice Choice, QuantisedMesh OnGrid);

    public static Result Run(string path)
    {
        var file = MeshReader.Read(path);
        var (mesh, zeroArea) = file.Mesh.WithoutDegenerate();
        if (mesh.Triangles.Count == 0)
            throw new MeshError(path, "triangles", zeroArea == 1 ? "the only triangle has zero area" : $"all {zeroArea} triangles have zero area");
        var choice = GridChoice.For(mesh, path);
        return new Result(file, zeroArea, choice, choice.Quantise(mesh, path));
    }

    /// <summary>Vertices, triangles, those dropped, bounds, the grid with the placement, and the largest vertex displacement.</summary>
    public static string Summary(Result r)
    {
        var mesh = r.File.Mesh;
        var (min, max) = mesh.Bounds;
        var dropped = r.ZeroArea + r.OnGrid.Collapsed;
        return string.Create(CultureInfo.InvariantCulture,
            $"mesh, {mesh.Vertices.Count} vertices, {mesh.Triangles.Count} triangles, {dropped} degenerate dropped " +
            $"({r.ZeroArea} of zero area, {r.OnGrid.Collapsed} collapsed on the grid), bounds {min}..{max}, " +
            $"{r.Choice.Grid} (moved by {r.Choice.Offset}; smallest edge {r.Choice.SmallestEdge:G4} = {r.Choice.StepsOnSmallestEdge:0.#} steps" +
            $"{(r.Choice.Capped ? $", fewer than {GridChoice.StepsPerSmallestEdge} as the grid is capped at {CoordinateGrid.MaxBits} bits" : "")}), " +
            $"largest vertex displacement {r.OnGrid.LargestDisplacement:G4} ({r.OnGrid.LargestDisplacement / r.Choice.Grid.Step:0.##} steps)");
    }
}
