using System.Text.RegularExpressions;

namespace QuantumRayTracing.Tests.Repository;

/// <summary>
/// Finds the places where a text of the project names a document that is not in the repository: Markdown links
/// in .md files, mentions of a *.md file anywhere, and relative paths that start with ../. Works on a list of the
/// repository's files (paths relative to its root, '/'-separated), so it needs no file system and can be tried
/// on made-up input.
/// </summary>
public sealed partial class DocumentReferences
{
    private readonly HashSet<string> _paths;
    private readonly HashSet<string> _fileNames;

    public DocumentReferences(IEnumerable<string> repositoryFiles)
    {
        var files = repositoryFiles.Select(f => f.Replace('\\', '/')).ToArray();
        _fileNames = files.Select(f => f[(f.LastIndexOf('/') + 1)..]).ToHashSet(StringComparer.Ordinal);
        // Every file and every directory above one: a link may name a folder.
        _paths = new HashSet<string>(StringComparer.Ordinal) { "" };
        foreach (var file in files)
            for (var path = file; path.Length > 0; path = path.Contains('/') ? path[..path.LastIndexOf('/')] : "")
                _paths.Add(path);
    }

    /// <summary>"file:line: names 'target', which is not in the repository" for every bad reference in <paramref name="text"/>.</summary>
    public IEnumerable<string> Problems(string file, string text)
    {
        var directory = file.Contains('/') ? file[..file.LastIndexOf('/')] : "";
        var lines = text.Split('\n');
        for (var k = 0; k < lines.Length; k++)
        {
            var line = lines[k];
            var targets = new List<string>();
            if (file.EndsWith(".md", StringComparison.Ordinal))
                targets.AddRange(MarkdownLink().Matches(line).Select(m => m.Groups["target"].Value).Where(IsLocal));
            targets.AddRange(MarkdownFileName().Matches(line).Select(m => m.Value));
            targets.AddRange(ParentPath().Matches(line).Select(m => m.Value));
            foreach (var target in targets.Distinct())
                if (!Resolves(directory, target))
                    yield return $"{file}:{k + 1}: names '{target}', which is not in the repository";
        }
    }

    private bool Resolves(string directory, string target)
    {
        var path = target.Split('#', '?')[0];
        if (path.Length == 0) return true; // a link to an anchor of the same page
        if (path.StartsWith('/')) return _paths.Contains(Normalise("", path.TrimStart('/')) ?? "\0");
        // A bare file name ("rendering.md") is fine anywhere in the repository; a path must resolve from the
        // file's folder, or name a repository path from the root or its tail.
        if (!path.Contains('/')) return _fileNames.Contains(path) || _paths.Contains(Normalise(directory, path) ?? "\0");
        if (Normalise(directory, path) is { } fromHere && _paths.Contains(fromHere)) return true;
        // Not relative to the file: a path from the root, or the tail of one (BadInput/README.md).
        return !path.StartsWith("../", StringComparison.Ordinal) && Normalise("", path) is { } tail
            && (_paths.Contains(tail) || _paths.Any(p => p.EndsWith("/" + tail, StringComparison.Ordinal)));
    }

    /// <summary><paramref name="path"/> resolved from <paramref name="directory"/>; null when it leaves the repository.</summary>
    private static string? Normalise(string directory, string path)
    {
        var parts = new List<string>(directory.Length == 0 ? [] : directory.Split('/'));
        foreach (var part in path.Split('/'))
        {
            if (part is "" or ".") continue;
            if (part == "..")
            {
                if (parts.Count == 0) return null;
                parts.RemoveAt(parts.Count - 1);
            }
            else parts.Add(part);
        }
        return string.Join('/', parts);
    }

    private static bool IsLocal(string target) => !UriScheme().IsMatch(target);

    [GeneratedRegex(@"\]\((?<target>[^)\s]+)(\s+""[^""]*"")?\)")]
    private static partial Regex MarkdownLink();

    [GeneratedRegex(@"(?<![\w./-])(\.{0,2}/)?[\w.-]+(/[\w.-]+)*\.md(?![\w])")]
    private static partial Regex MarkdownFileName();

    [GeneratedRegex(@"(?<![\w.])\.\./[\w./-]*[\w-]")]
    private static partial Regex ParentPath();

    [GeneratedRegex(@"^[a-zA-Z][a-zA-Z0-9+.-]*:")]
    private static partial Regex UriScheme();
}
