namespace QuantumRayTracing.Scenes.Generation;

/// <summary>
/// A small closed temple for indirect light (the paper's fig. 14): floor, four walls, a ceiling with a
/// square hole, four pillars and an altar, lit only by a directional light falling through the hole.
/// The camera stands inside, in front of the front wall, so every ray it or a bounce sends stays inside
/// or leaves through the hole; the filler squares sit behind the front wall, where no ray reaches.
/// No ambient term: what is not in the sunlit patch is lit only by indirect light (`render --vpl`).
/// </summary>
public static class TempleScene
{
    public const int Primitives = 32;

    // Interior: x 0..16, y 0..12, z 10..30; the hole spans x 5..11, z 17..23 in the ceiling (y = 12).
    private const int Height = 12;
    private const int Front = 10;

    public static SceneBuilder Build()
    {
        var scene = new SceneBuilder($"Temple, {Primitives} primitives, sunlight through the ceiling", integerBits: 5)
            .Material("stone", 0.75, 0.72, 0.65)
            .Material("wall", 0.7, 0.7, 0.72)
            .Material("pillar", 0.8, 0.78, 0.7)
            .Material("altar", 0.75, 0.3, 0.2)
            .Material("filler", 0.5, 0.5, 0.5)
            .Camera([8, 5.5, 11], [8, 3.5, 30], 65)
            .Ambient(0)
            // Travelling down, towards +z and −x: the sunlit patch falls on the floor left of the altar and up the left wall.
            .DirectionalLight([-0.5, -1, 0.3], 3);

        scene.Rectangle([0, 0, Front], [16, 0, 30], "stone")             // floor
            .Rectangle([0, 0, 30], [16, Height, 30], "wall")              // back
            .Rectangle([0, 0, Front], [0, Height, 30], "wall")            // left
            .Rectangle([16, 0, Front], [16, Height, 30], "wall")          // right
            .Rectangle([0, 0, Front], [16, Height, Front], "wall")        // front, behind the camera
            .Rectangle([0, Height, Front], [16, Height, 17], "stone")     // ceiling around the hole
            .Rectangle([0, Height, 23], [16, Height, 30], "stone")
            .Rectangle([0, Height, 17], [5, Height, 23], "stone")
            .Rectangle([11, Height, 17], [16, Height, 23], "stone");

        // Four square pillars from floor to ceiling, four faces each.
        foreach (var (x, z) in new[] { (2, 18), (12, 18), (2, 26), (12, 26) })
        {
            scene.Rectangle([x, 0, z], [x + 2, Height, z], "pillar")
                .Rectangle([x, 0, z + 2], [x + 2, Height, z + 2], "pillar")
                .Rectangle([x, 0, z], [x, Height, z + 2], "pillar")
                .Rectangle([x + 2, 0, z], [x + 2, Height, z + 2], "pillar");
        }

        // A low altar just behind the hole: top, front, back, sides.
        scene.Rectangle([6, 3, 24], [10, 3, 27], "altar")
            .Rectangle([6, 0, 24], [10, 3, 24], "altar")
            .Rectangle([6, 0, 27], [10, 3, 27], "altar")
            .Rectangle([6, 0, 24], [6, 3, 27], "altar")
            .Rectangle([10, 0, 24], [10, 3, 27], "altar");

        OutOfViewFiller.Fill(scene, Primitives, "filler");
        return scene;
    }
}
