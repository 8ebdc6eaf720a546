using Orleans.Runtime;
using Orleans.Placement;
using Orleans.Runtime.Placement;

namespace QuantumRayTracing.Cluster;

/// <summary>Places a grain on the silo its key names (<see cref="SiloAddress.ToParsableString"/>): one grain per worker.</summary>
[GenerateSerializer, Immutable, SuppressReferenceTracking]
public sealed class SiloKeyedPlacementStrategy : PlacementStrategy
{
    public static readonly SiloKeyedPlacementStrategy Instance = new();
}

/// <summary>Marks a grain class as placed by <see cref="SiloKeyedPlacementStrategy"/>.</summary>
[AttributeUsage(AttributeTargets.Class, AllowMultiple = false)]
public sealed class SiloKeyedPlacementAttribute() : PlacementAttribute(SiloKeyedPlacementStrategy.Instance);

/// <summary>Finds the silo a grain's key names; a silo that left the cluster cannot take the grain.</summary>
public sealed class SiloKeyedPlacementDirector : IPlacementDirector
{
    public Task<SiloAddress> OnAddActivation(PlacementStrategy strategy, PlacementTarget target, IPlacementContext context)
    {
        var key = target.GrainIdentity.Key.ToString();
        var silo = context.GetCompatibleSilos(target).FirstOrDefault(s => s.ToParsableString() == key)
            ?? throw new SiloUnavailableException($"worker {key} is not in the cluster");
        return Task.FromResult(silo);
    }
}
