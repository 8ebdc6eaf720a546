namespace QuantumRayTracing.Scenes.Generation;

/// <summary>
/// The Depth Complexity scene: every rectangle faces the camera. Seen from the camera, the upper-left
/// quadrant has 2 layers, the lower-right 9; the other two put a checkerboard in front of 1 and 4 layers. The 32 and 64 primitive versions differ only by filler behind the camera.
/// Which screen quadrant a world quadrant lands in follows the camera's orientation (docs/scenes.md).
/// </summary>
public static class DepthComplexityScene
{
    public static readonly int[] Sizes = [32, 64];

    public static SceneBuilder Build(int primitives)
    {
        var scene = new SceneBuilder($"Depth complexity, {primitives} primitives", integerBits: 5)
            .Material("near", 0.8, 0.3, 0.2)
            .Material("mid", 0.3, 0.7, 0.3)
            .Material("far", 0.25, 0.35, 0.8)
            .Material("check", 0.9, 0.9, 0.85)
            .Material("filler", 0.5, 0.5, 0.5)
            .Camera([16, 16, 3], [16, 16, 28], 60)
            .Light(16, 16, 4, 300);

        // Quadrant with 2 layers: x 1..15, y 17..31.
        foreach (var z in new[] { 20, 28 }) scene.Rectangle([1, 17, z], [15, 31, z], z == 20 ? "near" : "far");
        // Quadrant with 9 layers: x 17..31, y 1..15.
        for (var layer = 0; layer < 9; layer++)
            scene.Rectangle([17, 1, 12 + 2 * layer], [31, 15, 12 + 2 * layer], layer % 3 == 0 ? "near" : layer % 3 == 1 ? "mid" : "far");
        // Checkerboard over 1 back layer: x 17..31, y 17..31; 8 squares of a 4x4 board, then the back.
        Checkerboard(scene, 17, 17, z: 20);
        scene.Rectangle([17, 17, 28], [31, 31, 28], "far");
        // Checkerboard over 4 layers: x 1..15, y 1..15.
        Checkerboard(scene, 1, 1, z: 10);
        for (var layer = 0; layer < 4; layer++)
            scene.Rectangle([1, 1, 13 + 4 * layer], [15, 15, 13 + 4 * layer], layer % 2 == 0 ? "mid" : "far");

        OutOfViewFiller.Fill(scene, primitives, "filler");
        return scene;
    }

    /// <summary>Eight 3x3 squares, the dark cells of a 4x4 board spanning 14 units from (x0, y0), at depth z.</summary>
    private static void Checkerboard(SceneBuilder scene, int x0, int y0, int z)
    {
        int[] offsets = [0, 4, 8, 11];
        for (var row = 0; row < 4; row++)
            for (var column = 0; column < 4; column++)
                if ((row + column) % 2 == 0)
                    scene.Rectangle([x0 + offsets[column], y0 + offsets[row], z], [x0 + offsets[column] + 3, y0 + offsets[row] + 3, z], "check");
    }
}
