namespace QuantumRayTracing.Scenes.Generation;

/// <summary>
/// A scene of any number of rectangles on an integer grid of any width, for resource sweeps (the Qornell
/// box needs at least 8 primitives and a 5-bit grid). In a cube of side 2^c the rectangles take turns
/// facing z, x and y; each sits on one of the planes 1 … 2^c − 1 and spans the cube less an inset
/// that grows each time the planes run out; past that they repeat, which a sweep does not mind. The
/// camera looks along +z from just inside the z = 0 face, so camera rays meet every orientation. It stands
/// half a unit off the grid on every axis: at the cube's centre line it would lie on the x and y planes
/// through the centre, inside the rectangles there, which a scene may not have.
/// </summary>
public static class SweepScene
{
    public static SceneBuilder Build(int primitives, int coordinateBits)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(primitives, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(coordinateBits, 2);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(coordinateBits, 16);
        var side = 1 << coordinateBits;
        var top = side - 1;
        var centre = side / 2.0;
        var eye = centre + 0.5;
        var scene = new SceneBuilder($"sweep scene, {primitives} primitives, {coordinateBits}-bit grid", integerBits: coordinateBits)
            .Material("white", 0.75, 0.75, 0.75)
            .Camera([eye, eye, 0.5], [eye, eye, top], 60)
            .Light(centre, centre, 1, 10);
        var planes = top;          // 1 … 2^c − 1
        var insets = side / 2;     // spans [j, top − j] with j < side / 2 keep min < max
        for (var i = 0; i < primitives; i++)
        {
            var k = i / 3;
            var plane = 1 + k % planes;
            var inset = k / planes % insets;
            double low = inset, high = top - inset;
            switch (i % 3)
            {
                case 0: scene.Rectangle([low, low, plane], [high, high, plane], "white"); break;
                case 1: scene.Rectangle([plane, low, low], [plane, high, high], "white"); break;
                default: scene.Rectangle([low, plane, low], [high, plane, high], "white"); break;
            }
        }
        return scene;
    }
}
