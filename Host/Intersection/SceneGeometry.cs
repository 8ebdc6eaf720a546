using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// The scene's primitives as the oracle and the classical tests see them: one <see cref="PrimitiveRows"/> per run of
/// primitives of one kind (rectangles first, then triangles, as scenes are loaded), each on the scene's fixed-point
/// grid. Built once per scene.
/// </summary>
public sealed class SceneGeometry
{
    private readonly PrimitiveRows[] _kindOf;
    private readonly RectangleRows? _rectangles;

    public SceneGeometry(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        Grid = scene.Grid;
        Primitives = scene.Primitives;
        Count = scene.Primitives.Count;
        var kinds = new List<PrimitiveRows>();
        for (var first = 0; first < Count;)
        {
            var end = first + 1;
            while (end < Count && Primitives[end].GetType() == Primitives[first].GetType()) end++;
            kinds.Add(PrimitiveRows.For(Grid, first, [.. Primitives.Skip(first).Take(end - first)]));
            first = end;
        }
        Kinds = kinds;
        _kindOf = new PrimitiveRows[Count];
        foreach (var kind in kinds)
            for (var p = kind.First; p < kind.First + kind.Count; p++) _kindOf[p] = kind;
        if (kinds.Count == 1 && kinds[0] is RectangleRows rectangles) _rectangles = rectangles;
    }

    public CoordinateGrid Grid { get; }

    public IReadOnlyList<Primitive> Primitives { get; }

    /// <summary>The runs of primitives of one kind, in id order.</summary>
    public IReadOnlyList<PrimitiveRows> Kinds { get; }

    /// <summary>N, the number of primitives.</summary>
    public int Count { get; }

    /// <summary>Qubits of the index register: ceil(log2 N).</summary>
    public int IndexBits => SearchRegisters.For(Count).IndexQubits;

    /// <summary>Scale from world units to grid integers: 2^FractionBits.</summary>
    public double Scale => 1 << Grid.FractionBits;

    /// <summary>The kind primitive <paramref name="p"/> belongs to, with its tests.</summary>
    public PrimitiveRows KindOf(int p) => _kindOf[p];

    /// <summary>Whether every primitive is a rectangle: what the gate-level oracle builds circuits for.</summary>
    public bool RectanglesOnly => _rectangles is not null;

    /// <summary>The axis of rectangle <paramref name="p"/>'s plane normal (rectangle-only scenes: the gate-level oracle's input).</summary>
    public int FlatAxis(int p) => Rectangles.FlatAxis(p);

    /// <summary>The world coordinate of rectangle <paramref name="p"/>'s plane along its flat axis.</summary>
    public double PlaneOffset(int p) => Rectangles.PlaneOffset(p);

    /// <summary>Fixed-point minimum of rectangle <paramref name="p"/> along <paramref name="axis"/>.</summary>
    public int Min(int p, int axis) => Rectangles.Min(p, axis);

    /// <summary>The last grid cell of rectangle <paramref name="p"/> along <paramref name="axis"/>: its max corner minus one step, or the plane on the flat axis.</summary>
    public int Max(int p, int axis) => Rectangles.Max(p, axis);

    private RectangleRows Rectangles => _rectangles
        ?? throw new InvalidOperationException("the scene holds primitives other than rectangles; the gate-level oracle takes rectangles only");
}
