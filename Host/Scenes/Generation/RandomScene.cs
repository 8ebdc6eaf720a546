using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Scenes.Generation;

/// <summary>The kinds of random scene <see cref="RandomScene"/> draws: each stresses the renderer in one way.</summary>
public enum RandomSceneKind
{
    /// <summary>37 rectangles of random orientation, place and size: N not a power of two.</summary>
    Scattered,

    /// <summary>Rectangles facing the camera on three depths only, overlapping: many equal quantised depths, broken by id.</summary>
    Ties,

    /// <summary>Closed boxes in front of a tiled back wall: faces meeting along shared edges and tiles sharing sides.</summary>
    SharedEdges,

    /// <summary>4,000 small overlapping rectangles facing the camera: dozens of layers on a ray.</summary>
    Deep,

    /// <summary>Rectangles on a grid with 2 fraction bits (quarter units), random orientation.</summary>
    Fractional,
}

/// <summary>
/// Random axis-aligned scenes the renderer was not tuned on, drawn from a seed: a camera at z = 1
/// looking along +z into a 5-bit grid, one point light in front, six colours, and rectangles laid out
/// as <see cref="RandomSceneKind"/> says. The same kind and seed give the same scene.
/// </summary>
public static class RandomScene
{
    public static readonly RandomSceneKind[] Kinds = Enum.GetValues<RandomSceneKind>();

    public static Scene Build(RandomSceneKind kind, ulong seed)
    {
        var random = new SeededRandom(seed).Fork(RandomStreams.Scenario).Fork((ulong)kind);
        var builder = new SceneBuilder($"random {kind.ToString().ToLowerInvariant()} scene, seed {seed}", integerBits: 5, fractionBits: kind == RandomSceneKind.Fractional ? 2 : 0)
            .Material("c0", 0.8, 0.3, 0.2)
            .Material("c1", 0.3, 0.7, 0.3)
            .Material("c2", 0.25, 0.35, 0.8)
            .Material("c3", 0.9, 0.9, 0.85)
            .Material("c4", 0.8, 0.7, 0.2)
            .Material("c5", 0.6, 0.3, 0.7)
            .Camera([16, 16, 1], [16, 16, 31], 60)
            .Light(8 + random.NextInt(0, 16), 8 + random.NextInt(0, 16), 3, 400);
        string Colour() => $"c{random.NextInt(0, 5)}";
        switch (kind)
        {
            case RandomSceneKind.Scattered:
                for (var k = 0; k < 37; k++) Any(builder, random, Colour(), 1);
                break;
            case RandomSceneKind.Ties:
                int[] depths = [12, 18, 24];
                for (var k = 0; k < 24; k++)
                {
                    var (x, y) = (random.NextInt(0, 23), random.NextInt(0, 23));
                    var z = depths[random.NextInt(0, 2)];
                    builder.Rectangle([x, y, z], [x + random.NextInt(2, 8), y + random.NextInt(2, 8), z], Colour());
                }
                break;
            case RandomSceneKind.SharedEdges:
                Tiles(builder, random, Colour);
                for (var k = 0; k < 4; k++)
                {
                    var (x, y, z) = (random.NextInt(2, 22), random.NextInt(2, 22), random.NextInt(8, 20));
                    Box(builder, [x, y, z], [x + random.NextInt(2, 7), y + random.NextInt(2, 7), z + random.NextInt(2, 7)], Colour());
                }
                break;
            case RandomSceneKind.Deep:
                for (var k = 0; k < 4000; k++)
                {
                    var (x, y, z) = (random.NextInt(0, 27), random.NextInt(0, 27), random.NextInt(4, 31));
                    builder.Rectangle([x, y, z], [x + random.NextInt(1, 4), y + random.NextInt(1, 4), z], Colour());
                }
                break;
            case RandomSceneKind.Fractional:
                for (var k = 0; k < 29; k++) Any(builder, random, Colour(), 4);
                break;
        }
        return SceneLoader.Parse(builder.ToJson(), $"random-{kind.ToString().ToLowerInvariant()}-{seed}");
    }

    /// <summary>
    /// <paramref name="count"/> rectangles of random orientation, place and size (the scattered kind at any N), for how
    /// costs grow with N; the same count and seed give the same scene.
    /// </summary>
    public static Scene Scattered(int count, ulong seed)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(count, 1);
        var random = new SeededRandom(seed).Fork(RandomStreams.Scenario).Fork(1000 + (ulong)count);
        var builder = new SceneBuilder($"{count} random rectangles, seed {seed}", integerBits: 5)
            .Material("c0", 0.8, 0.3, 0.2)
            .Material("c1", 0.3, 0.7, 0.3)
            .Material("c2", 0.25, 0.35, 0.8)
            .Camera([16, 16, 1], [16, 16, 31], 60)
            .Light(8 + random.NextInt(0, 16), 8 + random.NextInt(0, 16), 3, 400);
        for (var k = 0; k < count; k++) Any(builder, random, $"c{random.NextInt(0, 2)}", 1);
        return SceneLoader.Parse(builder.ToJson(), $"random-{count}-{seed}");
    }

    // One rectangle: two in three face the camera, the rest face ±x or ±y; corners on a grid of 1/steps.
    private static void Any(SceneBuilder builder, SeededRandom random, string colour, int steps)
    {
        double Coordinate(int lo, int hi) => random.NextInt(lo * steps, hi * steps) / (double)steps;
        var axis = random.NextInt(0, 5) switch { < 4 => 2, 4 => 0, _ => 1 };
        var min = new double[3];
        var max = new double[3];
        for (var a = 0; a < 3; a++)
        {
            var (lo, hi) = a == 2 ? (6, 30) : (0, 30);
            min[a] = Coordinate(lo, hi - 1);
            max[a] = Math.Min(hi, min[a] + Coordinate(1, 12));
        }
        max[axis] = min[axis];
        builder.Rectangle(min, max, colour);
    }

    // A back wall at z = 30 cut into tiles at random columns and rows: neighbouring tiles share their sides.
    private static void Tiles(SceneBuilder builder, SeededRandom random, Func<string> colour)
    {
        int[] Cuts() => [0, .. Enumerable.Range(0, 3).Select(_ => random.NextInt(4, 27)).Distinct().Order(), 31];
        var (xs, ys) = (Cuts(), Cuts());
        for (var i = 0; i + 1 < xs.Length; i++)
            for (var j = 0; j + 1 < ys.Length; j++)
                builder.Rectangle([xs[i], ys[j], 30], [xs[i + 1], ys[j + 1], 30], colour());
    }

    // The six faces of a box: each meets four others along a shared edge.
    private static void Box(SceneBuilder builder, int[] min, int[] max, string colour)
    {
        for (var axis = 0; axis < 3; axis++)
            foreach (var side in new[] { min[axis], max[axis] })
            {
                double[] lo = [min[0], min[1], min[2]];
                double[] hi = [max[0], max[1], max[2]];
                lo[axis] = hi[axis] = side;
                builder.Rectangle(lo, hi, colour);
            }
    }
}
