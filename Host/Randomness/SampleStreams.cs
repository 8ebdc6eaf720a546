namespace QuantumRayTracing.Randomness;

/// <summary>
/// The generator of one Monte Carlo sample of a render (an area-light position, a VPL direction),
/// forked from the render's seed by a <see cref="RandomStreams"/> number and the sample's key (pixel,
/// surface point, light or VPL, sample index). A sample's numbers depend on nothing else: not on the
/// order passes visit samples, nor on how they are split into chunks, nor on how many other samples
/// there are — so renders are byte-identical per seed and a test can recompute any sample.
/// </summary>
public static class SampleStreams
{
    public static SeededRandom For(ulong seed, ulong stream, params ReadOnlySpan<long> key)
    {
        var random = new SeededRandom(seed).Fork(stream);
        foreach (var part in key) random = random.Fork((ulong)part);
        return random;
    }
}
