namespace QuantumRayTracing.Search {
    import QuantumRayTracing.Supersampling.SetDepolarizingRate;

    /// # Summary
    /// The lookup search's gates under a device noise model: H, X and Z each preceded by the one-qubit rate, CZ and
    /// CCNOT by the two-qubit rate (on every qubit they touch), and the uniform preparation as one such H per qubit,
    /// so N must be a power of two. The gates are not controllable: a controlled gate would need another arity's rate.
    internal function DeviceLookupGates(oneQubit : Double, twoQubit : Double) : LookupGates {
        let h = ApplyOneQubitGateOnDevice(oneQubit, H, _);
        new LookupGates {
            H = h,
            X = ApplyOneQubitGateOnDevice(oneQubit, X, _),
            Z = ApplyOneQubitGateOnDevice(oneQubit, Z, _),
            CZ = ApplyCzOnDevice(twoQubit, _, _),
            CCNOT = ApplyCcnotOnDevice(twoQubit, _, _, _),
            PrepareUniform = PrepareUniformWithHOnEveryQubit(h, _, _)
        }
    }

    // Each device gate sets its rate and then applies a self-adjoint gate. Its adjoint is declared `self`: a generated
    // adjoint would run the rate-setting call ahead of all the gates it reverses, not before each one.

    /// # Summary
    /// A self-adjoint one-qubit gate (H, X or Z) preceded by the one-qubit depolarizing rate.
    internal operation ApplyOneQubitGateOnDevice(oneQubit : Double, gate : Qubit => Unit is Adj + Ctl, target : Qubit) : Unit is Adj + Ctl {
        body (...) {
            SetDepolarizingRate(oneQubit);
            gate(target);
        }
        adjoint self;
        controlled (controls, ...) {
            FailControlledDeviceGate();
        }
        controlled adjoint self;
    }

    /// # Summary
    /// CZ preceded by the two-qubit depolarizing rate.
    internal operation ApplyCzOnDevice(twoQubit : Double, control : Qubit, target : Qubit) : Unit is Adj + Ctl {
        body (...) {
            SetDepolarizingRate(twoQubit);
            CZ(control, target);
        }
        adjoint self;
        controlled (controls, ...) {
            FailControlledDeviceGate();
        }
        controlled adjoint self;
    }

    /// # Summary
    /// CCNOT preceded by the two-qubit depolarizing rate, which then acts on each of its three qubits.
    internal operation ApplyCcnotOnDevice(twoQubit : Double, control1 : Qubit, control2 : Qubit, target : Qubit) : Unit is Adj + Ctl {
        body (...) {
            SetDepolarizingRate(twoQubit);
            CCNOT(control1, control2, target);
        }
        adjoint self;
        controlled (controls, ...) {
            FailControlledDeviceGate();
        }
        controlled adjoint self;
    }

    /// # Summary
    /// Fails: a device gate's rate is set for its own arity, which a control would change.
    internal function FailControlledDeviceGate() : Unit {
        fail "a device gate cannot be controlled: its rate is set for its own arity";
    }

    /// # Summary
    /// The uniform superposition over all 2^n basis states of `register` by `h` on every qubit; `count` must be 2^n.
    internal operation PrepareUniformWithHOnEveryQubit(h : Qubit => Unit is Adj + Ctl, count : Int, register : Qubit[]) : Unit is Adj + Ctl {
        if count != 1 <<< Length(register) {
            fail $"the device search runs N a power of two (its preparation is one H per qubit), got N = {count}";
        }
        ApplyToEachCA(h, register);
    }
}
