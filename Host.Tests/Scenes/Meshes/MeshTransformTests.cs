using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Meshes;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

public sealed class MeshTransformTests
{
    private static readonly Vec3 P = new(1, 2, 3);

    private static MeshTransform Rotate(double x, double y, double z) => new(Vec3.Zero, 1, new Vec3(x, y, z));

    /// <summary>
    /// Right-handed quarter turns of (1, 2, 3): about x, y → z and z → −y, so (1, −3, 2); about y, z → x and x → −z,
    /// so (3, 2, −1); about z, x → y and y → −x, so (−2, 1, 3). Exact: multiples of 90° use exact cosines and sines.
    /// </summary>
    [Fact]
    public void QuarterTurnsAboutEachAxis()
    {
        Assert.Equal(new Vec3(1, -3, 2), Rotate(90, 0, 0).Apply(P));
        Assert.Equal(new Vec3(3, 2, -1), Rotate(0, 90, 0).Apply(P));
        Assert.Equal(new Vec3(-2, 1, 3), Rotate(0, 0, 90).Apply(P));
        Assert.Equal(new Vec3(1, 3, -2), Rotate(-90, 0, 0).Apply(P));
        Assert.Equal(new Vec3(1, 2, 3), Rotate(360, -720, 0).Apply(P));
        Assert.Equal(new Vec3(-1, 2, -3), Rotate(0, 180, 0).Apply(P));
    }

    /// <summary>
    /// Scale first, then x, then y, then z, then translate: 2·(1, 2, 3) = (2, 4, 6); 90° about x: (2, −6, 4);
    /// 90° about y: (4, −6, −2); + (10, 20, 30) = (14, 14, 28). The other order (y before x) would give
    /// (6, 4, −2) → (6, 2, 4) → (16, 22, 34): the order is part of the contract.
    /// </summary>
    [Fact]
    public void ScaleThenRotateXThenYThenTranslate() =>
        Assert.Equal(new Vec3(14, 14, 28), new MeshTransform(new Vec3(10, 20, 30), 2, new Vec3(90, 90, 0)).Apply(P));

    /// <summary>x before z: 90° about x takes (1, 2, 3) to (1, −3, 2); 90° about z takes that to (3, 1, 2).</summary>
    [Fact]
    public void XBeforeZ() => Assert.Equal(new Vec3(3, 1, 2), Rotate(90, 0, 90).Apply(P));

    /// <summary>30° about z: (cos 30 − 2 sin 30, sin 30 + 2 cos 30, 3) = (√3/2 − 1, 1/2 + √3, 3).</summary>
    [Fact]
    public void AnyAngle()
    {
        var v = Rotate(0, 0, 30).Apply(P);
        Assert.Equal(Math.Sqrt(3) / 2 - 1, v.X, 1e-12);
        Assert.Equal(0.5 + Math.Sqrt(3), v.Y, 1e-12);
        Assert.Equal(3, v.Z);
    }

    [Fact]
    public void AppliesToEveryVertexOfAMesh()
    {
        var mesh = new TriangleMesh([new(0, 0, 0), new(1, 0, 0), new(0, 1, 0)], [new(0, 1, 2)]);
        var moved = new MeshTransform(new Vec3(5, 0, 0), 3, Vec3.Zero).Apply(mesh);
        Assert.Equal([new(5, 0, 0), new(8, 0, 0), new(5, 3, 0)], moved.Vertices);
        Assert.Equal(mesh.Triangles, moved.Triangles);
    }

    [Fact]
    public void ScaleMustBePositive()
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => new MeshTransform(Vec3.Zero, 0, Vec3.Zero));
        Assert.Throws<ArgumentOutOfRangeException>(() => new MeshTransform(Vec3.Zero, double.NaN, Vec3.Zero));
    }
}
