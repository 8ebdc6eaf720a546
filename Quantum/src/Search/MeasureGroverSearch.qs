namespace QuantumRayTracing.Search {
    import Std.Math.BitSizeI;

    /// # Summary
    /// Prepares the uniform superposition over `count` indices, applies `iterations` Grover
    /// iterations with the oracle marking `marked`, and measures the index register.
    ///
    /// # Input
    /// ## count
    /// Number of indices searched (N ≥ 1).
    /// ## marked
    /// Distinct marked indices, each in 0..count-1.
    /// ## iterations
    /// Number of Grover iterations r ≥ 0; r = 0 samples the uniform superposition.
    ///
    /// # Output
    /// The measured index, below `count` on an ideal machine (noise can flip it past; a lost qubit reads Zero).
    ///
    /// # Remarks
    /// Allocates ceil(log2 count) index qubits and the auxiliaries of `ApplyPhaseToAllOnes`,
    /// once for every gate of the search.
    /// When more than half the indices are marked the oracle marks the complement instead:
    /// that oracle is the original times −1, a global phase this uncontrolled search cannot see.
    internal operation MeasureGroverSearch(count : Int, marked : Int[], iterations : Int) : Int {
        CheckGroverSearch(count, marked, iterations);
        use index = Qubit[BitSizeI(count - 1)];
        use auxiliaries = Qubit[PhaseAuxiliaryCount(Length(index))];
        ApplyGroverSearch(IdealLookupGates(), count, marked, iterations, index, auxiliaries);
        MeasureIntegerReadingLossAsZero(index)
    }

    /// # Summary
    /// The search's gates before the measurement, in `gates`: the uniform preparation over `count` indices on `index`,
    /// then `iterations` Grover iterations marking `marked` (its complement when more than half is marked).
    internal operation ApplyGroverSearch(gates : LookupGates, count : Int, marked : Int[], iterations : Int, index : Qubit[], auxiliaries : Qubit[]) : Unit {
        let oracleSet = 2 * Length(marked) > count ? ComplementIndices(count, marked) | marked;
        gates.PrepareUniform(count, index);
        for _ in 1..iterations {
            ApplyGroverIteration(gates, count, oracleSet, index, auxiliaries);
        }
    }

    /// # Summary
    /// Fails unless `count` ≥ 1, `iterations` ≥ 0 and every marked index lies in 0..count-1.
    internal function CheckGroverSearch(count : Int, marked : Int[], iterations : Int) : Unit {
        if count < 1 {
            fail $"count must be at least 1, got {count}";
        }
        if iterations < 0 {
            fail $"iterations must be non-negative, got {iterations}";
        }
        for m in marked {
            if m < 0 or m >= count {
                fail $"marked index {m} is outside 0..{count - 1}";
            }
        }
    }

    /// # Summary
    /// Returns the indices in 0..count-1 that are not in `indices`, in ascending order.
    internal function ComplementIndices(count : Int, indices : Int[]) : Int[] {
        mutable isListed = [false, size = count];
        for i in indices {
            set isListed w/= i <- true;
        }
        mutable complement = [];
        for i in 0..count - 1 {
            if not isListed[i] {
                set complement += [i];
            }
        }
        complement
    }
}
