using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Rays;

/// <summary>
/// Primary rays of a pinhole camera, one through the centre of each pixel. Row 0 is the top of the
/// image; the image's right is up × forward, so with y up and the camera looking along +z, +x is on
/// the right.
/// </summary>
public static class CameraRays
{
    /// <summary>Rays in pixel order: index y · width + x.</summary>
    public static Ray[] For(Camera camera, int width, int height)
    {
        var at = Of(camera, width, height);
        var rays = new Ray[width * height];
        // Rows on all cores: each ray depends only on its pixel.
        Parallel.For(0, height, y =>
        {
            for (var x = 0; x < width; x++) rays[y * width + x] = at(y * width + x);
        });
        return rays;
    }

    /// <summary>The same rays as <see cref="For"/>, each computed when read: a render keeps no camera ray.</summary>
    public static ComputedList<Ray> Computed(Camera camera, int width, int height) => new(width * height, Of(camera, width, height));

    // The ray through pixel y · width + x.
    private static Func<int, Ray> Of(Camera camera, int width, int height)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        var forward = (camera.LookAt - camera.Position).Normalized();
        var right = camera.Up.Cross(forward).Normalized();
        var up = forward.Cross(right);
        var halfHeight = Math.Tan(camera.VerticalFov * Math.PI / 360);
        var halfWidth = halfHeight * width / height;
        return pixel =>
        {
            var (y, x) = Math.DivRem(pixel, width);
            var u = ((x + 0.5) / width * 2 - 1) * halfWidth;
            var v = (1 - (y + 0.5) / height * 2) * halfHeight;
            return new Ray(camera.Position, forward + u * right + v * up);
        };
    }
}
