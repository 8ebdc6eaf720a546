namespace QuantumRayTracing.Scenes.Generation;

/// <summary>
/// Pads a scene to N primitives with unit squares facing the camera in the layers z = 0 and z = 1,
/// behind the camera: no primary ray (which travels towards +z), mirror ray (the scenes' mirrors
/// face ±x, so reflection keeps z increasing) or shadow ray (between points inside the scene) can
/// reach them. They grow the search space without changing the image or any ray's t.
/// </summary>
public static class OutOfViewFiller
{
    public static void Fill(SceneBuilder scene, int primitives, string material)
    {
        var needed = primitives - scene.Count;
        if (needed > 512) throw new ArgumentOutOfRangeException(nameof(primitives), primitives, "at most 512 filler squares fit behind the camera");
        for (var k = 0; k < needed; k++)
        {
            var layer = k / 256;
            var x = k % 16 * 2;
            var y = k % 256 / 16 * 2;
            scene.Rectangle([x, y, layer], [x + 1, y + 1, layer], material);
        }
    }
}
