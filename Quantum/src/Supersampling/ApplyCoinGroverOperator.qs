namespace QuantumRayTracing.Supersampling {
    import Std.Arrays.Most;
    import Std.Arrays.Tail;

    /// # Summary
    /// The amplitude-amplification operator G = −A S₀ A† S_χ of a coin: S_χ flips the sign of
    /// the head, A† undoes the coin, S₀ flips the sign of |0…0⟩, A prepares it again. It rotates
    /// by 2θ in the plane of head and tail, sin²θ the head probability, so after m applications
    /// the head has probability sin²((2m+1)θ). It calls the oracle twice (in A and A†): two queries.
    ///
    /// # Input
    /// ## prepare
    /// The coin A on `qubits`.
    /// ## markHead
    /// A phase of −1 on the head states, identity elsewhere.
    /// ## qubits
    /// The coin's qubits (subpixel register and coin qubit).
    ///
    /// # Remarks
    /// The global sign −1 is applied (X Z X Z = −I): QSS runs G under counter qubits, where it
    /// becomes a relative phase, and the eigenphases ±2θ that the inverse QFT reads assume it.
    internal operation ApplyCoinGroverOperator(
        prepare : (Qubit[] => Unit is Adj + Ctl),
        markHead : (Qubit[] => Unit is Adj + Ctl),
        qubits : Qubit[]
    ) : Unit is Adj + Ctl {
        markHead(qubits);
        Adjoint prepare(qubits);
        within {
            ApplyToEachCA(X, qubits);
        } apply {
            Controlled Z(Most(qubits), Tail(qubits));
        }
        prepare(qubits);
        let last = Tail(qubits);
        X(last);
        Z(last);
        X(last);
        Z(last);
    }
}
