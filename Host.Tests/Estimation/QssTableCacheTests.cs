using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Estimation;

public sealed class QssTableCacheTests : IDisposable
{
    private readonly string _directory = Path.Combine(Path.GetTempPath(), "qrt-qss-cache-" + Guid.NewGuid().ToString("N"));

    public void Dispose()
    {
        if (Directory.Exists(_directory)) Directory.Delete(_directory, recursive: true);
    }

    [Fact]
    public void SecondRunReadsTheTableInsteadOfBuildingIt()
    {
        var builds = 0;
        QssLookupTable Build() { builds++; return QssLookupTable.Exact(16, 4); }
        var first = new QssTableCache(_directory).GetOrBuild(16, 4, "exact", Build);
        var cache = new QssTableCache(_directory);
        var second = cache.GetOrBuild(16, 4, "exact", Build);
        Assert.Equal(1, builds);
        Assert.True(cache.LastWasHit);
        Assert.Equal(first.Probabilities, second.Probabilities);
        Assert.Equal(first.HitsOfReadout, second.HitsOfReadout);
    }

    [Theory]
    [InlineData("not json at all")]
    [InlineData("{\"format\":\"qrt-qss-lookup-table/1\",\"subpixels\":16,\"counterBits\":4,\"source\":\"exact\",\"probabilities\":[[1]]}")]
    [InlineData("[1, 2, 3]")]
    [InlineData("")]
    public void CorruptFileIsRebuilt(string contents)
    {
        var cache = new QssTableCache(_directory);
        Directory.CreateDirectory(_directory);
        File.WriteAllText(cache.PathFor(16, 4, "exact"), contents);
        var builds = 0;
        var table = cache.GetOrBuild(16, 4, "exact", () => { builds++; return QssLookupTable.Exact(16, 4); });
        Assert.Equal(1, builds);
        Assert.False(cache.LastWasHit);
        Assert.Equal(17, table.Probabilities.GetLength(1));
        // The rebuilt table replaced the corrupt file.
        Assert.NotNull(QssTableCache.TryRead(cache.PathFor(16, 4, "exact"), 16, 4, "exact"));
    }

    [Fact]
    public void TableOfAnotherKeyIsNotUsed()
    {
        var cache = new QssTableCache(_directory);
        Directory.CreateDirectory(_directory);
        // A valid table for 4 subpixels stored under the name of the 16-subpixel key.
        File.WriteAllText(cache.PathFor(16, 4, "exact"), QssTableCache.Serialize(QssLookupTable.Exact(4, 4)));
        var builds = 0;
        cache.GetOrBuild(16, 4, "exact", () => { builds++; return QssLookupTable.Exact(16, 4); });
        Assert.Equal(1, builds);
    }

    [Fact]
    public void UnwritableCacheStillGivesTheTable()
    {
        // A file where the cache directory should be: nothing can be stored, the table is still returned.
        File.WriteAllText(_directory, "x");
        try
        {
            var table = new QssTableCache(_directory).GetOrBuild(4, 2, "exact", () => QssLookupTable.Exact(4, 2));
            Assert.Equal(4, table.Readouts);
        }
        finally
        {
            File.Delete(_directory);
        }
    }
}
