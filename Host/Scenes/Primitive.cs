using System.Text.Json.Serialization;

namespace QuantumRayTracing.Scenes;

/// <summary>
/// A primitive of a scene: a flat shape on the scene's grid with a material. <see cref="Id"/> is its index in the scene
/// and the tie-breaker of equal depths. Each kind lives in a file of its own (<see cref="Rectangle"/>,
/// <see cref="Triangle"/>), as does its classical test (Host/Intersection); docs/architecture.md lists where a kind is added.
/// </summary>
/// <remarks>Serialised with its kind's name (a scene goes to cluster workers as JSON): each kind is listed here.</remarks>
[JsonPolymorphic(TypeDiscriminatorPropertyName = "kind")]
[JsonDerivedType(typeof(Rectangle), "rectangle")]
[JsonDerivedType(typeof(Triangle), "triangle")]
public abstract record Primitive(int Id, Material Material)
{
    /// <summary>The smallest axis-aligned box holding the primitive, in world units.</summary>
    [JsonIgnore]
    public abstract (Vec3 Min, Vec3 Max) Bounds { get; }

    /// <summary>A unit normal of the primitive's plane (either side).</summary>
    [JsonIgnore]
    public abstract Vec3 Normal { get; }

    /// <summary>Whether <paramref name="point"/> lies on the primitive, edges included.</summary>
    public abstract bool Contains(Vec3 point);

    /// <summary>The unit normal on the side a ray of direction <paramref name="direction"/> comes from.</summary>
    public Vec3 FacingNormal(Vec3 direction)
    {
        var normal = Normal;
        // Zero minus the normal, not its negation: a zero component stays +0, never −0 (1 / −0 is −∞ further on).
        return normal.Dot(direction) > 0 ? Vec3.Zero - normal : normal;
    }
}
