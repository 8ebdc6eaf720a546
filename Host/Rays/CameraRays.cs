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
        var at = Of(camera, ImageWindow.Whole(width, height));
        var rays = new Ray[width * height];
        // Rows on all cores: each ray depends only on its pixel.
        Parallel.For(0, height, y =>
        {
            for (var x = 0; x < width; x++) rays[y * width + x] = at(y * width + x);
        });
        return rays;
    }

    /// <summary>The same rays as <see cref="For"/>, each computed when read: a render keeps no camera ray.</summary>
    public static ComputedList<Ray> Computed(Camera camera, int width, int height) => Computed(camera, ImageWindow.Whole(width, height));

    /// <summary>The rays of <paramref name="window"/>'s pixels, in its own pixel order (y · its width + x), each computed when read.</summary>
    public static ComputedList<Ray> Computed(Camera camera, ImageWindow window) => new(window.Width * window.Height, Of(camera, window));

    // The ray through the window's pixel y · width + x: the whole image's pixel (X + x, Y + y).
    private static Func<int, Ray> Of(Camera camera, ImageWindow window)
    {
        var (width, height) = (window.FullWidth, window.FullHeight);
        ArgumentOutOfRangeException.ThrowIfLessThan(window.Width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(window.Height, 1);
        if (window.X < 0 || window.Y < 0 || window.X + window.Width > width || window.Y + window.Height > height)
            throw new ArgumentOutOfRangeException(nameof(window), window, "the window reaches outside its image");
        var forward = (camera.LookAt - camera.Position).Normalized();
        var right = camera.Up.Cross(forward).Normalized();
        var up = forward.Cross(right);
        var halfHeight = Math.Tan(camera.VerticalFov * Math.PI / 360);
        var halfWidth = halfHeight * width / height;
        // A ray is read many times in a render: each column's step along right and each row's along up are computed once.
        var across = Enumerable.Range(window.X, window.Width).Select(x => ((x + 0.5) / width * 2 - 1) * halfWidth * right).ToArray();
        var down = Enumerable.Range(window.Y, window.Height).Select(y => (1 - (y + 0.5) / height * 2) * halfHeight * up).ToArray();
        return pixel =>
        {
            var (y, x) = Math.DivRem(pixel, window.Width);
            return new Ray(camera.Position, forward + across[x] + down[y]);
        };
    }
}
