namespace QuantumRayTracing.Scenes.Generation;

/// <summary>
/// The Qornell box: an open-fronted 16x16x16 box on a 5-bit grid, a mirror on its left wall, a tall
/// and a short block, two point lights under the ceiling. 14 primitives are in view (8 at N = 8);
/// the rest are filler behind the camera (<see cref="OutOfViewFiller"/>). <see cref="BuildAreaLit"/>
/// is the same box lit by one area light on the ceiling instead (the paper's fig. 13).
/// </summary>
public static class QornellBox
{
    public static readonly int[] Sizes = [8, 16, 32, 64, 128, 256, 512];

    /// <summary>The area-lit box's sizes: the paper's fig. 13 uses 64 primitives.</summary>
    public static readonly int[] AreaLitSizes = [64];

    public static SceneBuilder Build(int primitives) =>
        Box(primitives, $"Qornell box, {primitives} primitives", scene => scene.Light(5, 15, 21, 60).Light(11, 15, 17, 40));

    /// <summary>
    /// The box with a 6x6 area light in the ceiling's plane (y = 16) over its centre instead of the point
    /// lights. In the ceiling's plane, a shadow ray ends exactly there (t = 1) and the ceiling cannot occlude it.
    /// </summary>
    public static SceneBuilder BuildAreaLit(int primitives) =>
        Box(primitives, $"Qornell box, {primitives} primitives, ceiling area light", scene => scene.AreaLight([5, 16, 19], [11, 16, 25], 6));

    private static SceneBuilder Box(int primitives, string name, Action<SceneBuilder> lights)
    {
        if (primitives < 8) throw new ArgumentOutOfRangeException(nameof(primitives), primitives, "the Qornell box needs at least 8 primitives");
        var scene = new SceneBuilder(name, integerBits: 5)
            .Material("white", 0.75, 0.75, 0.75)
            .Material("red", 0.75, 0.15, 0.12)
            .Material("green", 0.15, 0.7, 0.2)
            .Material("mirror", 0.05, 0.05, 0.05, mirror: 0.9)
            .Material("block", 0.7, 0.65, 0.5)
            .Material("filler", 0.5, 0.5, 0.5)
            .Camera([8, 8, 2], [8, 8, 22], 60);
        lights(scene);

        // Walls: floor, ceiling, back, left (mirror), right; the front (towards the camera) is open.
        scene.Rectangle([0, 0, 14], [16, 0, 30], "white")
            .Rectangle([0, 16, 14], [16, 16, 30], "white")
            .Rectangle([0, 0, 30], [16, 16, 30], "white")
            .Rectangle([0, 0, 14], [0, 16, 30], "mirror")
            .Rectangle([16, 0, 14], [16, 16, 30], "green");

        // Blocks, most visible faces first so that N = 8 keeps the short block's visible faces.
        var faces = new List<(double[] Min, double[] Max, string Material)>
        {
            ([9, 4, 17], [13, 4, 21], "block"),  // short block: top
            ([9, 0, 17], [13, 4, 17], "block"),  //   front
            ([9, 0, 17], [9, 4, 21], "block"),   //   left, facing the camera's side
            ([3, 9, 20], [7, 9, 24], "red"),     // tall block: top
            ([3, 0, 20], [7, 9, 20], "red"),     //   front
            ([7, 0, 20], [7, 9, 24], "red"),     //   right, facing the camera's side
            ([3, 0, 20], [3, 9, 24], "red"),     //   left, towards the mirror
            ([3, 0, 24], [7, 9, 24], "red"),     //   back
            ([13, 0, 17], [13, 4, 21], "block"), // short block: right
        };
        foreach (var face in faces.Take(Math.Min(faces.Count, primitives - scene.Count)))
            scene.Rectangle(face.Min, face.Max, face.Material);

        OutOfViewFiller.Fill(scene, primitives, "filler");
        return scene;
    }
}
