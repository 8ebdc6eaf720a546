namespace QuantumRayTracing.Output.Plots;

/// <summary>An 8-bit RGB colour used by the plot writer.</summary>
public readonly record struct PlotColour(byte R, byte G, byte B)
{
    /// <summary>Pure black, used for axes and text.</summary>
    public static PlotColour Black => new(0, 0, 0);

    /// <summary>Pure white, the background.</summary>
    public static PlotColour White => new(255, 255, 255);
}
