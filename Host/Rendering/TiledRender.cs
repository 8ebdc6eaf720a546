using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// A large render in tiles (<see cref="ImageTiles"/>): each tile's pixels, with a border as wide as the coarsest lattice step,
/// rendered on their own by <see cref="SceneRenderer"/> with a seed of the tile's own, and its interior copied into the image.
/// A render then holds the image and the work of the tiles running at once, not every pixel's, and a tile renders the same whenever it runs. Each
/// tile keeps the budget for its own pixels (its allowance is the budget's share of its interior, spent on its traced pixels),
/// so the image keeps it too; the border's rays are traced and counted in every tile that traces them. Where the tiles render
/// (<see cref="IPartRenderer"/>: two at a time here, several at once on a cluster's workers) does not change the image.
/// </summary>
public static class TiledRender
{
    /// <summary>The side of a tile's own pixels: a multiple of every lattice step.</summary>
    public const int TileSize = 512;

    /// <summary>Renders from this many pixels on are tiled (<see cref="RenderForecast.LargePixels"/>, where the forecast starts).</summary>
    public static bool Applies(RenderOptions options) => (long)options.Width * options.Height >= RenderForecast.LargePixels;

    /// <summary>The most pixels one tile traces: its own and, on each side, a border of the coarsest lattice step.</summary>
    public static long MostTracedPixels(int latticeLevels) => (long)(TileSize + 2 * (1 << latticeLevels)) * (TileSize + 2 * (1 << latticeLevels));

    /// <summary>A tile's seed: the render's seed forked for the tile, so no two tiles draw alike.</summary>
    public static ulong TileSeed(ulong seed, int tile) => new SeededRandom(seed).Fork(RandomStreams.Tiles + (ulong)tile).NextUInt64();

    /// <param name="parts">Renders a tile's part, here or on a cluster's workers.</param>
    /// <param name="options">The whole render's options.</param>
    /// <param name="progress">Told the tiles' progress as one stage, "n tiles".</param>
    /// <param name="tileSize">The side of a tile's own pixels, a multiple of the coarsest lattice step.</param>
    public static RenderResult Render(IPartRenderer parts, RenderOptions options, IRenderProgress? progress = null, int tileSize = TileSize)
    {
        var step = 1 << options.LatticeLevels;
        if (tileSize % step != 0) throw new ArgumentException($"tiles of {tileSize} pixels do not hold whole lattice steps of {step}", nameof(tileSize));
        var tiles = ImageTiles.Of(options.Width, options.Height, tileSize, step);
        var image = new RgbImage(options.Width, options.Height);
        var passes = new PassMetrics[tiles.Count][];
        var expected = new double[tiles.Count];
        var lightErrors = new Metrics.LightError?[tiles.Count];
        var stage = TileProgress.StageOf(tiles.Count);
        void Run(ImageTile tile, IRenderProgress? tileProgress)
        {
            var traced = tile.Traced;
            var tileOptions = options with
            {
                Width = traced.Width, Height = traced.Height, Seed = TileSeed(options.Seed, tile.Index),
                Budget = options.Budget * tile.Interior.Pixels / traced.Pixels,
            };
            var part = parts.Render(tileOptions, traced, tileProgress);
            // Tiles own disjoint pixels: tiles rendered at once copy into the image side by side.
            for (var y = 0; y < tile.Interior.Height; y++)
                for (var x = 0; x < tile.Interior.Width; x++)
                {
                    var (r, g, b) = part.Image.GetPixel(tile.Interior.X - traced.X + x, tile.Interior.Y - traced.Y + y);
                    image.SetPixel(tile.Interior.X + x, tile.Interior.Y + y, r, g, b);
                }
            passes[tile.Index] = [.. part.Passes];
            expected[tile.Index] = part.Budget.ExpectedWrongPixels;
            lightErrors[tile.Index] = part.LightError;
        }
        if (parts.Concurrency <= 1)
        {
            var tileProgress = progress is null ? null : new TileProgress(progress, tiles.Count);
            foreach (var tile in tiles)
            {
                tileProgress?.Start(tile.Index);
                Run(tile, tileProgress);
            }
        }
        else
        {
            // Parts rendered at once report only when they are done.
            var done = 0;
            progress?.Report(stage, 0);
            try
            {
                Parallel.ForEach(tiles, new ParallelOptions { MaxDegreeOfParallelism = parts.Concurrency }, tile =>
                {
                    Run(tile, null);
                    progress?.Report(stage, (double)Interlocked.Increment(ref done) / tiles.Count);
                });
            }
            catch (AggregateException e)
            {
                // The first failure as itself (a cluster's, a worker's request error), as a render one part at a time raises it.
                System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(e.InnerExceptions[0]).Throw();
                throw;
            }
        }
        // Every tile runs the same passes in the same order; each pass's metrics are summed over the tiles, in tile order.
        progress?.Report(stage, 1);
        var merged = Enumerable.Range(0, passes[0].Length).Select(k => PassMetrics.Total(passes[0][k].Name, [.. passes.Select(p => p[k])])).ToArray();
        var expectedWrong = 0.0;
        foreach (var e in expected) expectedWrong += e;
        // Estimated light's error over every point each tile estimated (its apron's too).
        var lightError = options.Light is null ? null : lightErrors.Aggregate(Metrics.LightError.None, (sum, e) => e is null ? sum : sum.Add(e));
        return new RenderResult(image, merged) { Budget = new AccuracyBudget(expectedWrong, (long)options.Width * options.Height, options.Budget), LightError = lightError };
    }

    // The whole render as one stage, "n tiles": the tiles done, and of the running tile the share of its passes done (counted
    // from the first tile, which runs the same passes), so the time left is the render's.
    private sealed class TileProgress(IRenderProgress inner, int tiles) : IRenderProgress
    {
        private readonly List<string> _passes = [];
        private (int Tile, int Pass, string? Stage) _at;

        public static string StageOf(int tiles) => $"{tiles} tiles";

        public string Stage => StageOf(tiles);

        public void Start(int tile)
        {
            _at = (tile, -1, null);
            inner.Report(Stage, (double)tile / tiles);
        }

        public void Report(string stage, double done)
        {
            if (stage != _at.Stage)
            {
                _at = (_at.Tile, _at.Pass + 1, stage);
                if (_at.Tile == 0) _passes.Add(stage);
            }
            var share = _at.Tile == 0 || _passes.Count == 0 ? 0 : Math.Min(1, (_at.Pass + Math.Clamp(done, 0, 1)) / _passes.Count);
            inner.Report(Stage, (_at.Tile + share) / tiles);
        }
    }
}
