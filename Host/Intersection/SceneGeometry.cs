using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// The scene's primitives as the oracle sees them: each rectangle's bounds as fixed-point grid
/// integers (value · 2^FractionBits), its flat axis and plane. Built once per scene.
/// </summary>
/// <remarks>
/// Bounds are the grid cells a quantised point may fall in. Points are quantised by flooring, so a
/// rectangle spanning [a, b) on an axis holds the cells a … b − 1 (one step below its max corner):
/// with the inclusive comparison verify-rpc makes, a point is inside exactly when a ≤ value &lt; b, and
/// rectangles that share an edge never both claim a point. On the flat axis min = max = the plane.
/// </remarks>
public sealed class SceneGeometry
{
    private readonly int[] _min;
    private readonly int[] _max;
    private readonly int[] _flat;
    private readonly double[] _plane;

    // Structure-of-arrays columns for the vectorised row kernel (CompactRows): per axis, the bounds as doubles (grid
    // integers are exact in a double) and the flat-axis masks as all-ones or zero lanes.
    internal readonly double[][] MinColumns = [[], [], []];
    internal readonly double[][] MaxColumns = [[], [], []];
    internal readonly long[][] FlatMasks = [[], [], []];
    internal readonly double[] Planes;

    public SceneGeometry(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        Grid = scene.Grid;
        Rectangles = scene.Rectangles;
        Count = scene.Rectangles.Count;
        _min = new int[Count * 3];
        _max = new int[Count * 3];
        _flat = scene.Rectangles.Select(r => r.FlatAxis).ToArray();
        _plane = scene.Rectangles.Select(r => r.PlaneOffset).ToArray();
        for (var p = 0; p < Count; p++)
            for (var axis = 0; axis < 3; axis++)
            {
                _min[p * 3 + axis] = ToGrid(scene.Rectangles[p].Min[axis], p);
                var max = ToGrid(scene.Rectangles[p].Max[axis], p);
                _max[p * 3 + axis] = axis == scene.Rectangles[p].FlatAxis ? max : max - 1;
            }
        Planes = _plane;
        for (var axis = 0; axis < 3; axis++)
        {
            var a = axis;
            MinColumns[a] = [.. Enumerable.Range(0, Count).Select(p => (double)_min[p * 3 + a])];
            MaxColumns[a] = [.. Enumerable.Range(0, Count).Select(p => (double)_max[p * 3 + a])];
            FlatMasks[a] = [.. _flat.Select(f => f == a ? -1L : 0L)];
        }
    }

    public CoordinateGrid Grid { get; }

    public IReadOnlyList<Rectangle> Rectangles { get; }

    /// <summary>N, the number of primitives.</summary>
    public int Count { get; }

    /// <summary>Qubits of the index register: ceil(log2 N).</summary>
    public int IndexBits => SearchRegisters.For(Count).IndexQubits;

    /// <summary>The axis of primitive <paramref name="p"/>'s plane normal (kept in an array: eval-rpc reads it for every row).</summary>
    public int FlatAxis(int p) => _flat[p];

    /// <summary>The world coordinate of primitive <paramref name="p"/>'s plane along its flat axis.</summary>
    public double PlaneOffset(int p) => _plane[p];

    /// <summary>Fixed-point minimum of primitive <paramref name="p"/> along <paramref name="axis"/>.</summary>
    public int Min(int p, int axis) => _min[p * 3 + axis];

    /// <summary>The last grid cell of primitive <paramref name="p"/> along <paramref name="axis"/>: its max corner minus one step, or the plane on the flat axis.</summary>
    public int Max(int p, int axis) => _max[p * 3 + axis];

    /// <summary>Scale from world units to grid integers: 2^FractionBits.</summary>
    public double Scale => 1 << Grid.FractionBits;

    private int ToGrid(double value, int p) =>
        Grid.ToFixed(value) ?? throw new ArgumentException($"rectangle {p}: coordinate {value} is not on the {Grid}");
}
