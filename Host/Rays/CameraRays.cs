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
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        var forward = (camera.LookAt - camera.Position).Normalized();
        var right = camera.Up.Cross(forward).Normalized();
        var up = forward.Cross(right);
        var halfHeight = Math.Tan(camera.VerticalFov * Math.PI / 360);
        var halfWidth = halfHeight * width / height;
        var rays = new Ray[width * height];
        // Rows on all cores: each ray depends only on its pixel.
        Parallel.For(0, height, y =>
        {
            for (var x = 0; x < width; x++)
            {
                var u = ((x + 0.5) / width * 2 - 1) * halfWidth;
                var v = (1 - (y + 0.5) / height * 2) * halfHeight;
                rays[y * width + x] = new Ray(camera.Position, forward + u * right + v * up);
            }
        });
        return rays;
    }
}
