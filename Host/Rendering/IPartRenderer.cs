using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// Renders one part of an image with <see cref="SceneRenderer"/>: the whole image, or a tile's window with options of its
/// own (<see cref="TiledRender"/>). A part renders the same wherever it runs: here (<see cref="LocalParts"/>) or on a
/// cluster's workers (<see cref="RemoteParts"/>), so where the parts run never changes the image.
/// </summary>
public interface IPartRenderer
{
    /// <summary>How many parts are rendered at once: here two on the engines searching in this process (<see cref="LocalParts.TilesAtOnce"/>), the workers' capacity on a cluster.</summary>
    int Concurrency { get; }

    /// <summary>The part <paramref name="window"/> (null: the whole image) at <paramref name="options"/>; told its passes' progress where it runs here.</summary>
    RenderResult Render(RenderOptions options, ImageWindow? window, IRenderProgress? progress);
}
