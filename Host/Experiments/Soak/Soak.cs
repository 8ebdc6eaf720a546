using System.Diagnostics;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// Renders every scene on every engine with every seed through `render`'s default pipeline (without the accuracy budget) and checks
/// each render: it finishes without an exception; its radiance is finite and its PNG decodes back to its
/// pixels; on the classical engine it equals the classical reference, on the quantum engines it stays
/// within <see cref="DifferentPixelBound"/> of it; on the seedable engines (analytic, classical,
/// randomized) a second render of the same seed gives the same PNG bytes at the same search cost; and a second seed changes what
/// it should: the render of the analytic and randomized engines (its image, or where both images are
/// exact its search cost), the classical image only when the scene samples light. A search the simulator
/// refuses before simulating (<see cref="SimulatorLimitException"/>: a gate search wider than the engine's
/// qubit limit, a fullstate one wider than the machine holds), and a gate render forecast
/// (<see cref="GateCostEstimate"/>) to exceed the budget, are skipped, not failed.
/// </summary>
public static class Soak
{
    /// <summary>
    /// One row per scene and engine (one row for a scene file that does not load), scenes by primitive
    /// count then name. <paramref name="render"/> renders a scene on an engine with options (the seed theirs); <paramref name="progress"/> gets a label per render; <paramref name="onRow"/> each finished row.
    /// </summary>
    public static IReadOnlyList<SoakRow> Run(IReadOnlyList<string> sceneFiles, SoakSettings settings, Func<Scene, EngineKind, RenderOptions, IRenderProgress?, RenderResult> render,
        Func<string, IRenderProgress?>? progress = null, Action<SoakRow>? onRow = null)
    {
        var scenes = sceneFiles.Select(Load).OrderBy(s => s.Scene is null).ThenBy(s => s.Scene?.Primitives.Count ?? 0)
            .ThenBy(s => s.Stem, StringComparer.Ordinal).ToArray();
        var smallest = scenes.Where(s => s.Scene is not null).Select(s => s.Scene!.Primitives.Count).DefaultIfEmpty(0).Min();
        var rows = new List<SoakRow>();
        void Add(SoakRow row)
        {
            rows.Add(row);
            onRow?.Invoke(row);
        }
        foreach (var (stem, scene, error) in scenes)
        {
            if (scene is null)
            {
                Add(new SoakRow(stem, 0, null, SoakStatus.Failed, error!));
                continue;
            }
            var references = new Dictionary<(int Size, ulong Seed), RenderResult>();
            foreach (var kind in settings.Engines)
                Add(new SceneRun(stem, scene, kind, settings, render, progress, references).Row(smallest));
        }
        return rows;
    }

    private static (string Stem, Scene? Scene, string? Error) Load(string file)
    {
        var stem = Path.GetFileNameWithoutExtension(file);
        try
        {
            return (stem, SceneLoader.Load(file), null);
        }
        catch (Exception e) when (e is SceneError or UserError or IOException or UnauthorizedAccessException)
        {
            return (stem, null, "scene does not load: " + OneLine(e.Message));
        }
    }

    private static string OneLine(string message) => message.ReplaceLineEndings(" ").Trim();

    /// <summary>One render: its result, PNG bytes and wall time.</summary>
    private sealed record Rendered(RenderResult Result, byte[] Png, TimeSpan WallTime);

    /// <summary>One scene on one engine, over every seed.</summary>
    private sealed class SceneRun(string stem, Scene scene, EngineKind kind, SoakSettings settings, Func<Scene, EngineKind, RenderOptions, IRenderProgress?, RenderResult> render,
        Func<string, IRenderProgress?>? progress, Dictionary<(int Size, ulong Seed), RenderResult> references)
    {
        private readonly List<string> _failures = [];
        private readonly List<TimeSpan> _times = [];
        private int Primitives => scene.Primitives.Count;

        public SoakRow Row(int smallest)
        {
            if (kind.RunsQSharp && settings.SimulatorsOnSmallestSceneOnly && Primitives > smallest)
                return SoakRow.Skipped(stem, Primitives, kind, $"short form: simulators on the smallest scene only (N = {smallest})");
            var size = settings.SizeFor(kind);
            if (kind.SimulatesOracleGates && GateCostEstimate.Of(scene, settings.Options(size, settings.Seeds[0])) is var forecast && forecast > settings.GateBudget)
                return SoakRow.Skipped(stem, Primitives, kind, $"forecast {Seconds(forecast)} per render, over the gate budget of {Seconds(settings.GateBudget)}");

            var firsts = new List<Rendered>();
            var errors = new List<ImageError>();
            var bound = kind.SearchesWithGrover ? DifferentPixelBound.Max(size * size) : (int?)null;
            bool? deterministic = kind.IsSeedable ? true : null;
            var seedEffect = "";
            var seed = settings.Seeds[0];
            try
            {
                foreach (var s in settings.Seeds)
                {
                    seed = s;
                    var options = settings.Options(size, seed);
                    var first = Render(options, "");
                    firsts.Add(first);
                    var error = ImageError.Between(first.Result.Image, Reference(options));
                    errors.Add(error);
                    if (kind.IsExact && error.DifferentPixels != 0)
                        Fail($"{error.DifferentPixels} pixels differ from the classical reference");
                    if (bound is { } most && error.DifferentPixels > most)
                        Fail($"#Dpix {error.DifferentPixels} against the classical render, over the bound of {most}");
                    if (deterministic is null) continue;
                    var again = Render(options, ", again");
                    if (!again.Png.AsSpan().SequenceEqual(first.Png))
                    {
                        deterministic = false;
                        Fail($"a second render differs ({ImageError.Between(again.Result.Image, first.Result.Image).DifferentPixels} pixels)");
                    }
                    else if (!Costs(again.Result).SequenceEqual(Costs(first.Result)))
                    {
                        deterministic = false;
                        Fail("a second render gives the same image at another search cost");
                    }
                }
                seedEffect = SeedEffect(firsts);
            }
            catch (QubitLimitException e)
            {
                return SoakRow.Skipped(stem, Primitives, kind, $"needs {e.Registers.PeakQubits} qubits, over the limit of {e.Limit}");
            }
            catch (SimulatorLimitException e)
            {
                return SoakRow.Skipped(stem, Primitives, kind, OneLine(e.Message));
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                Fail($"{e.GetType().Name}: {OneLine(e.Message)}");
            }

            return new SoakRow(stem, Primitives, kind, _failures.Count == 0 ? SoakStatus.Ok : SoakStatus.Failed, string.Join("; ", _failures),
                size, _times.Count, _times.Count == 0 ? default : TimeSpan.FromTicks((long)_times.Average(t => t.Ticks)),
                firsts.Count == 0 ? null : firsts.Average(r => r.Result.Total.PerRayConservative),
                errors.Count == 0 ? null : errors.Max(e => e.Nrmse), errors.Count == 0 ? null : errors.Max(e => e.DifferentPixels),
                bound, deterministic, seedEffect);

            void Fail(string reason) => _failures.Add(settings.Seeds.Count > 1 ? $"seed {seed}: {reason}" : reason);
        }

        private Rendered Render(RenderOptions options, string repeat)
        {
            var clock = Stopwatch.StartNew();
            var result = render(scene, kind, options, progress?.Invoke($"{stem} on {kind.Name}, seed {options.Seed}{repeat}"));
            var wall = clock.Elapsed;
            _times.Add(wall);
            var png = PngWriter.Encode(result.Image);
            if (result.Radiance.Any(c => !double.IsFinite(c.X) || !double.IsFinite(c.Y) || !double.IsFinite(c.Z)))
                _failures.Add($"seed {options.Seed}{repeat}: radiance not finite at {result.Radiance.Count(c => !double.IsFinite(c.X + c.Y + c.Z))} pixels");
            if (!ImageReader.Decode(png, "render").Pixels.SequenceEqual(result.Image.Pixels))
                _failures.Add($"seed {options.Seed}{repeat}: the PNG does not decode to the rendered pixels");
            return new Rendered(result, png, wall);
        }

        // The classical render every engine's render of these options is compared with; its seed matters only when light is sampled.
        private RgbImage Reference(RenderOptions options)
        {
            if (!references.TryGetValue((options.Width, options.Seed), out var reference))
            {
                reference = Renderer.Render(scene, new EngineSetup(EngineKind.Classical), RenderDefaults.Reference(options));
                references[(options.Width, options.Seed)] = reference;
            }
            return reference.Image;
        }

        // What the second and later seeds changed against the first, and a failure where that is not what the engine should do.
        private string SeedEffect(List<Rendered> firsts)
        {
            if (firsts.Count < 2) return "n.a. (one seed)";
            var image = firsts.Skip(1).Any(r => !r.Png.AsSpan().SequenceEqual(firsts[0].Png));
            var cost = firsts.Skip(1).Any(r => !Costs(r.Result).SequenceEqual(Costs(firsts[0].Result)));
            var effect = image ? "image" : cost ? "cost only" : "none";
            var samples = RenderDefaults.SamplesLight(scene, settings.Options(1, 1));
            if (kind.DrawsFromSeed && effect == "none")
                _failures.Add("every seed gives the same image and the same search cost: the seed is not used");
            else if (kind.IsExact && samples && !image)
                _failures.Add("every seed gives the same image although the scene samples light");
            else if (kind.IsExact && !samples && effect != "none")
                _failures.Add($"the seed changes the {(image ? "image" : "search cost")} although the scene samples no light");
            return effect;
        }

        // A render's cost, pass by pass, without the wall times.
        private static IEnumerable<(string, long, int, SearchCost, long, long)> Costs(RenderResult result) =>
            result.Passes.Select(p => (p.Name, p.Rays, p.Iterations, p.Cost, p.TableRows, p.UpdatedPixels));
    }

    private static string Seconds(TimeSpan time) => string.Create(System.Globalization.CultureInfo.InvariantCulture, $"{time.TotalSeconds:0} s");
}
