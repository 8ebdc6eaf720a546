namespace QuantumRayTracing.Estimation;

/// <summary>
/// The single-ancilla (Kitaev, iterative) phase-estimation shot, <see cref="Shots"/> times: an ancilla in |+⟩, the mean coin
/// prepared, the ancilla controlling <see cref="Power"/> Grover operators Q^k, the ancilla measured in the X basis; the engine
/// returns the number of shots whose ancilla read 0.
/// </summary>
/// <remarks>
/// The coin A|0⟩ = sinθ|good⟩ + cosθ|bad⟩ is an equal-weight superposition of Q's eigenvectors, eigenphases ±2θ, so
/// ⟨ψ|Q^k|ψ⟩ = cos(2kθ) is real, and with a phase β on the ancilla's |1⟩ the ancilla reads 0 with probability
/// ½ + ½·cos(2kθ)·cos β: β only scales the contrast, so the shot takes β = 0 and P(0) = cos²(kθ).
/// </remarks>
/// <param name="Amplitudes">√F(i) per subpixel, as <see cref="CoinRequest.Amplitudes"/> of the mean coin.</param>
/// <param name="Power">k ≥ 0 controlled Grover operators.</param>
/// <param name="Shots">Shots, ≥ 0.</param>
public sealed record AncillaPhaseRequest(double[] Amplitudes, int Power, int Shots)
{
    /// <summary>docs/conventions.md: the coin's preparation one query, each (controlled) Grover operator two.</summary>
    public long Queries => (long)Shots * (1 + 2L * Power);

}
