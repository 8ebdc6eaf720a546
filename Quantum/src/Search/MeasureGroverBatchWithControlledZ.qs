namespace QuantumRayTracing.Search {
    import Std.Math.BitSizeI;
    import Std.Measurement.MeasureInteger;

    /// # Summary
    /// `MeasureGroverBatch` with the first construction of the oracle and of S₀ (the standard
    /// library's multi-controlled Z on a flag qubit): the baseline the benchmarks compare with.
    ///
    /// # Input
    /// ## requests
    /// One `(count, marked, iterations)` tuple per search, as taken by `MeasureGroverSearch`.
    ///
    /// # Output
    /// The measured index of each request, in request order.
    operation MeasureGroverBatchWithControlledZ(requests : (Int, Int[], Int)[]) : Int[] {
        mutable measured = [];
        for (count, marked, iterations) in requests {
            let oracleSet = 2 * Length(marked) > count ? ComplementIndices(count, marked) | marked;
            use index = Qubit[BitSizeI(count - 1)];
            use flag = Qubit();
            within {
                X(flag);
            } apply {
                PrepareUniformSuperposition(count, index);
                for _ in 1..iterations {
                    ApplyMarkingOracleWithControlledZ(oracleSet, index, flag);
                    ReflectAboutUniformSuperposition(count, Controlled Z(_, flag), index);
                }
            }
            set measured += [MeasureInteger(index)];
        }
        measured
    }
}
