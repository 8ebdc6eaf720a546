namespace QuantumRayTracing.Supersampling {
    import Std.Arrays.Most;
    import Std.Arrays.Tail;

    /// # Summary
    /// S_χ of QCoin's shifted coin, R_{|1⟩|0)} of paper 003 (eq. 41): a phase of −1 on the coin
    /// qubit's |1⟩ when the subpixel register reads 0.
    internal operation MarkShiftedCoinHead(register : Qubit[]) : Unit is Adj + Ctl {
        ApplyControlledOnInt(0, Z, Most(register), Tail(register));
    }
}
