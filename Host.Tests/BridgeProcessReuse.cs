using System.Runtime.CompilerServices;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Tests;

/// <summary>
/// The whole test run shares its Node bridge processes: every command, pool and engine a test starts takes an idle process
/// whose Q# sources are already compiled, instead of starting and compiling one of its own (<see cref="QSharpBridge.ReuseProcesses"/>).
/// Tests that kill, time out or break a bridge still get a fresh process for it.
/// </summary>
internal static class BridgeProcessReuse
{
#pragma warning disable CA2255 // A test assembly sets a process-wide switch before any test runs; xunit 2 has no assembly fixture.
    [ModuleInitializer]
    internal static void Enable() => QSharpBridge.ReuseProcesses = true;
#pragma warning restore CA2255
}
