namespace QuantumRayTracing.Supersampling {
    import Std.Math.ArcSin;
    import Std.Math.PI;
    import Std.Convert.IntAsDouble;
    import QuantumRayTracing.Search.MeasureIntegerReadingLossAsZero;

    /// # Summary
    /// The QCoin paper's device QSS (sec. 6, fig. 9 top): no subpixel register, a single-qubit coin
    /// √(1 − f)|0⟩ + √f|1⟩ prepared by one Ry, counter qubit j controlling 2^j Grover operators
    /// Q Z Q⁻¹ Z (eq. 45) with every gate of the operator under the control, the inverse QFT with
    /// the register reversal by SWAPs, and the counter measured. Written in one- and two-qubit gates
    /// only, each followed by depolarizing noise at its own rate, so the run follows a device model.
    ///
    /// # Input
    /// ## oneQubit
    /// Depolarizing probability after each one-qubit gate (H, Ry, Rz).
    /// ## twoQubit
    /// Depolarizing probability on each qubit after each two-qubit gate (CNOT, CZ).
    /// ## headAmplitude
    /// √f in [0, 1].
    /// ## counterBits
    /// t ≥ 1 counter qubits: 2^t − 1 Grover operators, 2^(t+1) − 1 queries.
    ///
    /// # Output
    /// The counter readout y in 0..2^t − 1, before any readout error; noiseless, distributed as
    /// `MeasureQssReadout` on a coin of mean f.
    ///
    /// # Remarks
    /// A controlled Ry(a) is Ry(a/2), CNOT, Ry(−a/2), CNOT; a controlled phase e^{iφ} is Rz(φ/2) on
    /// both qubits and Rz(−φ/2) on the target between two CNOTs; a SWAP is three CNOTs.
    operation MeasureDirectQssOnDevice(oneQubit : Double, twoQubit : Double, headAmplitude : Double, counterBits : Int) : Int {
        if counterBits < 1 {
            fail $"counterBits must be at least 1, got {counterBits}";
        }
        let angle = 2.0 * ArcSin(headAmplitude);
        use counter = Qubit[counterBits];
        use coin = Qubit();
        SetDepolarizingRate(oneQubit);
        ApplyToEach(H, counter);
        Ry(angle, coin);
        for j in 0..counterBits - 1 {
            for _ in 1..1 <<< j {
                ApplyDeviceCZ(twoQubit, counter[j], coin);
                ApplyDeviceControlledRy(oneQubit, twoQubit, -angle, counter[j], coin);
                ApplyDeviceCZ(twoQubit, counter[j], coin);
                ApplyDeviceControlledRy(oneQubit, twoQubit, angle, counter[j], coin);
            }
        }
        // Qubit j holds the binary fraction 0.y_{j+1}…y_t: from the top qubit down, remove the bits already
        // read and apply H; qubit j then holds y_{j+1}, the most significant bit at qubit 0.
        for j in counterBits - 1..-1..0 {
            for k in j + 1..counterBits - 1 {
                ApplyDeviceControlledPhase(oneQubit, twoQubit, -2.0 * PI() / IntAsDouble(1 <<< (k - j + 1)), counter[k], counter[j]);
            }
            SetDepolarizingRate(oneQubit);
            H(counter[j]);
        }
        for j in 0..counterBits / 2 - 1 {
            ApplyDeviceCnot(twoQubit, counter[j], counter[counterBits - 1 - j]);
            ApplyDeviceCnot(twoQubit, counter[counterBits - 1 - j], counter[j]);
            ApplyDeviceCnot(twoQubit, counter[j], counter[counterBits - 1 - j]);
        }
        SetDepolarizingRate(0.0);
        let readout = MeasureIntegerReadingLossAsZero(counter);
        Reset(coin);
        readout
    }

    /// # Summary
    /// CZ followed by two-qubit noise.
    internal operation ApplyDeviceCZ(twoQubit : Double, control : Qubit, target : Qubit) : Unit {
        SetDepolarizingRate(twoQubit);
        CZ(control, target);
    }

    /// # Summary
    /// CNOT followed by two-qubit noise.
    internal operation ApplyDeviceCnot(twoQubit : Double, control : Qubit, target : Qubit) : Unit {
        SetDepolarizingRate(twoQubit);
        CNOT(control, target);
    }

    /// # Summary
    /// Ry(a) on `target` controlled by `control`: Ry(a/2), CNOT, Ry(−a/2), CNOT, each with its rate.
    internal operation ApplyDeviceControlledRy(oneQubit : Double, twoQubit : Double, angle : Double, control : Qubit, target : Qubit) : Unit {
        SetDepolarizingRate(oneQubit);
        Ry(angle / 2.0, target);
        ApplyDeviceCnot(twoQubit, control, target);
        SetDepolarizingRate(oneQubit);
        Ry(-angle / 2.0, target);
        ApplyDeviceCnot(twoQubit, control, target);
    }

    /// # Summary
    /// The phase e^{iφ} on |11⟩ (up to a global phase): Rz(φ/2) on both qubits, then Rz(−φ/2) on the
    /// target between two CNOTs, each with its rate.
    internal operation ApplyDeviceControlledPhase(oneQubit : Double, twoQubit : Double, phase : Double, control : Qubit, target : Qubit) : Unit {
        SetDepolarizingRate(oneQubit);
        Rz(phase / 2.0, control);
        Rz(phase / 2.0, target);
        ApplyDeviceCnot(twoQubit, control, target);
        SetDepolarizingRate(oneQubit);
        Rz(-phase / 2.0, target);
        ApplyDeviceCnot(twoQubit, control, target);
    }
}
