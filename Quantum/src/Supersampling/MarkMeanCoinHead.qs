namespace QuantumRayTracing.Supersampling {
    import Std.Arrays.Tail;

    /// # Summary
    /// S_χ of the mean coin: a phase of −1 wherever the coin qubit (last in `register`) is |1⟩.
    internal operation MarkMeanCoinHead(register : Qubit[]) : Unit is Adj + Ctl {
        Z(Tail(register));
    }
}
