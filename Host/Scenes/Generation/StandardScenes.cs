using QuantumRayTracing.Output;

namespace QuantumRayTracing.Scenes.Generation;

/// <summary>The scene files in Scenes/: the Qornell boxes, Depth Complexity, the area-lit Qornell box and the temple.</summary>
public static class StandardScenes
{
    /// <summary>Every generated scene: file name and builder.</summary>
    public static IEnumerable<(string File, SceneBuilder Scene)> All() =>
        QornellBox.Sizes.Select(n => ($"qornell-{n}.json", QornellBox.Build(n)))
            .Concat(DepthComplexityScene.Sizes.Select(n => ($"depth-complexity-{n}.json", DepthComplexityScene.Build(n))))
            .Concat(QornellBox.AreaLitSizes.Select(n => ($"qornell-{n}-area.json", QornellBox.BuildAreaLit(n))))
            .Append(($"temple-{TempleScene.Primitives}.json", TempleScene.Build()));

    /// <summary>
    /// Writes every scene into <paramref name="directory"/> under the marker naming <paramref name="commandLine"/>, after checking
    /// that no file there is someone else's; <paramref name="wrote"/> hears of each file and its primitive count.
    /// </summary>
    public static void Write(string directory, string commandLine, Action<string, int> wrote)
    {
        var files = All().Select(s => (Path: Path.Combine(directory, s.File), s.Scene)).ToArray();
        var marker = GeneratedReport.JsonMarker(commandLine);
        foreach (var (path, _) in files) new GeneratedReport(path, marker).EnsureWritable();
        foreach (var (path, scene) in files)
        {
            var report = new GeneratedReport(path, marker);
            var text = scene.ToJson();
            SceneLoader.Parse(report.Compose(text), path); // a generator bug must not reach disk
            report.Write(text);
            wrote(path, scene.Count);
        }
    }
}
