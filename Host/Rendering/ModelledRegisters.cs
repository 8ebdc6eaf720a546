using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// What a render models, known before it runs: the scene's primitives, the registers of one lookup search (index
/// qubits and the auxiliaries of its multi-controlled phase), the coordinate bits per axis, and with the gate
/// engine the oracle registers of the centre pixel's primary search (depth bits, and so the width, vary by ray).
/// </summary>
public sealed record ModelledRegisters(int Primitives, int IndexQubits, int AuxiliaryQubits, int CoordinateBits, OracleRegisters? GateRegisters)
{
    public static ModelledRegisters Of(RenderRunSettings settings)
    {
        var (scene, width, height) = (settings.Scene, settings.Options.Width, settings.Options.Height);
        var geometry = new SceneGeometry(scene);
        OracleRegisters? gate = null;
        if (settings.Engine.Kind.SimulatesOracleGates)
        {
            var centre = RayTable.Build(geometry, CameraRays.For(scene.Camera, width, height)[height / 2 * width + width / 2]);
            gate = OracleRegisters.For(new OracleInput(centre, centre.FullRange));
        }
        return new ModelledRegisters(geometry.Count, geometry.IndexBits, SearchRegisters.For(geometry.Count).AuxiliaryQubits, scene.Grid.Bits, gate);
    }
}
