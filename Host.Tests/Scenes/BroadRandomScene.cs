using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Tests.Scenes;

/// <summary>The layouts <see cref="BroadRandomScene"/> draws, each hard for the pipeline in its own way.</summary>
public enum BroadSceneKind
{
    /// <summary>Rectangles of random orientation, place and size.</summary>
    Scattered,

    /// <summary>A few tight clusters of small rectangles: neighbouring pixels see different primitives.</summary>
    Clusters,

    /// <summary>Thin slivers one grid cell wide: a pixel's neighbours often miss them.</summary>
    Slivers,

    /// <summary>Rectangles whose plane runs along the view direction, seen edge-on or nearly so.</summary>
    EdgeOn,

    /// <summary>Overlapping rectangles facing the camera on two or three depths: many equal depths, broken by id.</summary>
    Ties,

    /// <summary>Small occluders between the light and a back wall: small shadows neighbours disagree on.</summary>
    SmallShadows,
}

/// <summary>
/// Random scenes broader than the benchmark's (<see cref="RandomScene"/>): 6 to 200 primitives (half of them 24 to 64),
/// never a power of two, in every <see cref="BroadSceneKind"/>, with a camera at z = 1 looking along +z into a 5-bit grid and one
/// or two point lights. The same seed gives the same scene; the kind and N are drawn from it too.
/// </summary>
public static class BroadRandomScene
{
    public const int MinPrimitives = 6;
    public const int MaxPrimitives = 200;

    public static readonly BroadSceneKind[] Kinds = Enum.GetValues<BroadSceneKind>();

    /// <summary>The scene of <paramref name="kind"/> for <paramref name="seed"/>, with <paramref name="primitives"/> or, when null, an N drawn from the seed.</summary>
    public static Scene Build(BroadSceneKind kind, ulong seed, int? primitives = null)
    {
        var random = new SeededRandom(seed).Fork(RandomStreams.Scenario).Fork(100 + (ulong)kind);
        // Half the scenes anywhere in 6..200, half in 24..64, where neither the classical settle nor a deep search hides misses.
        var count = random.NextInt(0, 1) == 0 ? random.NextInt(MinPrimitives, MaxPrimitives) : random.NextInt(24, 64);
        if ((count & (count - 1)) == 0) count++; // never a power of two
        count = primitives ?? count;
        var builder = new SceneBuilder($"broad random {kind}, {count} primitives, seed {seed}", integerBits: 5)
            .Material("c0", 0.8, 0.3, 0.2)
            .Material("c1", 0.3, 0.7, 0.3)
            .Material("c2", 0.25, 0.35, 0.8)
            .Material("c3", 0.9, 0.9, 0.85)
            .Material("m", 0.2, 0.2, 0.2, mirror: 0.6)
            .Camera([16, 16, 1], [16, 16, 31], 60)
            .Light(4 + random.NextInt(0, 24), 4 + random.NextInt(0, 24), 3 + random.NextInt(0, 4), 400);
        if (random.NextInt(0, 1) == 1) builder.Light(4 + random.NextInt(0, 24), 4 + random.NextInt(0, 24), 2, 250);
        string Colour() => random.NextInt(0, 12) == 0 ? "m" : $"c{random.NextInt(0, 3)}";
        int Int(int lo, int hi) => random.NextInt(lo, hi);
        void Add(int[] min, int[] max) => builder.Rectangle([min[0], min[1], min[2]], [max[0], max[1], max[2]], Colour());
        switch (kind)
        {
            case BroadSceneKind.Scattered:
                while (builder.Count < count) Add(Facing(random, out var hi), hi);
                break;
            case BroadSceneKind.Clusters:
                var centres = Enumerable.Range(0, Int(2, 4)).Select(_ => (X: Int(6, 24), Y: Int(6, 24), Z: Int(10, 26))).ToArray();
                while (builder.Count < count)
                {
                    var c = centres[Int(0, centres.Length - 1)];
                    var (x, y, z) = (Clamp(c.X + Int(-4, 4), 0, 29), Clamp(c.Y + Int(-4, 4), 0, 29), Clamp(c.Z + Int(-3, 3), 4, 30));
                    Add([x, y, z], [x + Int(1, 2), y + Int(1, 2), z]);
                }
                break;
            case BroadSceneKind.Slivers:
                while (builder.Count < count)
                {
                    var (x, y, z) = (Int(0, 29), Int(0, 29), Int(6, 30));
                    var along = Int(3, 16);
                    if (Int(0, 1) == 0) Add([x, y, z], [x + 1, Math.Min(31, y + along), z]);
                    else Add([x, y, z], [Math.Min(31, x + along), y + 1, z]);
                }
                break;
            case BroadSceneKind.EdgeOn:
                Add([0, 0, 30], [31, 31, 30]);
                while (builder.Count < count)
                {
                    // Planes x = const or y = const near the view axis, extending in depth: the camera sees them edge-on.
                    var (a, b, z) = (Int(13, 19), Int(2, 26), Int(6, 22));
                    if (Int(0, 1) == 0) Add([a, b, z], [a, b + Int(1, 5), z + Int(2, 8)]);
                    else Add([b, a, z], [b + Int(1, 5), a, z + Int(2, 8)]);
                }
                break;
            case BroadSceneKind.Ties:
                int[] depths = [.. Enumerable.Range(0, Int(2, 3)).Select(_ => Int(8, 28)).Distinct()];
                while (builder.Count < count)
                {
                    var (x, y) = (Int(0, 25), Int(0, 25));
                    var z = depths[Int(0, depths.Length - 1)];
                    Add([x, y, z], [x + Int(2, 6), y + Int(2, 6), z]);
                }
                break;
            case BroadSceneKind.SmallShadows:
                Add([0, 0, 30], [31, 31, 30]);
                while (builder.Count < count)
                {
                    var (x, y, z) = (Int(2, 28), Int(2, 28), Int(5, 26));
                    Add([x, y, z], [x + 1, y + Int(1, 2), z]);
                }
                break;
        }
        return SceneLoader.Parse(builder.ToJson(), $"broad-{kind.ToString().ToLowerInvariant()}-{seed}");
    }

    /// <summary><paramref name="count"/> rectangles of random orientation, place and size (<see cref="BroadSceneKind.Scattered"/> at any N).</summary>
    public static Scene Scattered(int count, ulong seed)
    {
        var random = new SeededRandom(seed).Fork(RandomStreams.Scenario).Fork(200);
        var builder = new SceneBuilder($"{count} random rectangles, seed {seed}", integerBits: 5)
            .Material("c0", 0.8, 0.3, 0.2)
            .Material("c1", 0.3, 0.7, 0.3)
            .Material("c2", 0.25, 0.35, 0.8)
            .Camera([16, 16, 1], [16, 16, 31], 60)
            .Light(4 + random.NextInt(0, 24), 4 + random.NextInt(0, 24), 3, 400);
        while (builder.Count < count)
        {
            var min = Facing(random, out var max);
            builder.Rectangle([min[0], min[1], min[2]], [max[0], max[1], max[2]], $"c{random.NextInt(0, 2)}");
        }
        return SceneLoader.Parse(builder.ToJson(), $"random-{count}-{seed}");
    }

    // A rectangle of random orientation (two in three face the camera) inside the grid, depth at least 6.
    private static int[] Facing(SeededRandom random, out int[] max)
    {
        var axis = random.NextInt(0, 5) switch { < 4 => 2, 4 => 0, _ => 1 };
        var min = new int[3];
        max = new int[3];
        for (var a = 0; a < 3; a++)
        {
            var (lo, hi) = a == 2 ? (6, 30) : (0, 30);
            min[a] = random.NextInt(lo, hi - 1);
            max[a] = Math.Min(hi, min[a] + random.NextInt(1, 12));
        }
        max[axis] = min[axis];
        return min;
    }

    private static int Clamp(int value, int lo, int hi) => Math.Max(lo, Math.Min(hi, value));
}
