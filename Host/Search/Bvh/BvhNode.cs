namespace QuantumRayTracing.Search.Bvh;

/// <summary>
/// One node of a flattened BVH. A leaf holds <see cref="Count"/> primitives from <see cref="First"/> in the
/// hierarchy's primitive order; an interior node's first child follows it and its second is at
/// <see cref="SecondChild"/>, split along <see cref="Axis"/>.
/// </summary>
public readonly record struct BvhNode(BoundingBox Bounds, int First, int Count, int SecondChild, int Axis)
{
    public bool IsLeaf => Count > 0;
}
