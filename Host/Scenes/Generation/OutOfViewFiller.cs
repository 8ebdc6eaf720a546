namespace QuantumRayTracing.Scenes.Generation;

/// <summary>
/// Pads a scene to N primitives with unit squares behind the camera (z ≤ 2): no primary ray (which
/// travels towards +z from z = 2), mirror ray (the scenes' mirrors face ±x, so reflection keeps z
/// increasing) or shadow ray (between points inside the scene) can reach them. They grow the search
/// space without changing the image or any ray's t. The first 512 face the camera in the layers
/// z = 0 and z = 1; beyond those (up to <see cref="Capacity"/>), squares facing ±x, then ±y, stand in
/// the slab 0 ≤ z ≤ 2.
/// </summary>
public static class OutOfViewFiller
{
    private const int FacingCamera = 512;
    private const int PerSide = 32 * 31 * 2; // planes 0..31, unit cells 0..30 along the other axis, z cells 0 and 1

    /// <summary>The most filler squares a 5-bit grid holds this way (a few fewer where the camera stands on one).</summary>
    public const int Capacity = FacingCamera + 2 * PerSide;

    public static void Fill(SceneBuilder scene, int primitives, string material)
    {
        var needed = primitives - scene.Count;
        var camera = scene.CameraPosition;
        // A square the camera stands on (the loader refuses it) is skipped for the next one.
        bool HoldsCamera(double[] min, double[] max) => Enumerable.Range(0, 3).All(a => min[a] <= camera[a] && camera[a] <= max[a]);
        var placed = 0;
        for (var k = 0; placed < needed; k++)
        {
            if (k >= Capacity) throw new ArgumentOutOfRangeException(nameof(primitives), primitives, $"at most {Capacity} filler squares fit behind the camera");
            double[] min, max;
            if (k < FacingCamera)
            {
                var layer = k / 256;
                var x = k % 16 * 2;
                var y = k % 256 / 16 * 2;
                (min, max) = ([x, y, layer], [x + 1, y + 1, layer]);
            }
            else
            {
                var j = (k - FacingCamera) % PerSide;
                var (plane, cell, z) = (j / 62, j % 62 / 2, j % 2);
                if (k - FacingCamera < PerSide) (min, max) = ([plane, cell, z], [plane, cell + 1, z + 1]);
                else (min, max) = ([cell, plane, z], [cell + 1, plane, z + 1]);
            }
            if (HoldsCamera(min, max)) continue;
            scene.Rectangle(min, max, material);
            placed++;
        }
    }
}
