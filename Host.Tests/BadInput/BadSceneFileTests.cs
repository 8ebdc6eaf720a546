namespace QuantumRayTracing.Tests.BadInput;

/// <summary>
/// Every file in BadInput/Scenes (but the baseline valid.json, of which each is a copy with one defect) through
/// the three commands that read scenes. Each case names the element the error must point at and a phrase of the
/// problem; the first comment line of each file says what is wrong with it.
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class BadSceneFileTests : IDisposable
{
    private readonly ScratchDirectory _output = new("qrt-bad-scene-");

    public void Dispose() => _output.Dispose();

    /// <summary>File → element → phrase of the problem.</summary>
    public static TheoryData<string, string, string> Cases => new()
    {
        // Not JSON, or not a scene object.
        { "malformed-json.json", "rectangles[1]", "is not valid JSON (line 9" },
        { "empty-file.json", "$", "the file is empty" },
        { "not-an-object.json", "$", "expected an object" },
        { "duplicate-field.json", "image", "appears twice" },
        // Wrong types.
        { "wrong-type-width.json", "image.width", "expected a whole number" },
        { "wrong-type-fractional-width.json", "image.width", "expected a whole number" },
        { "wrong-type-rectangles.json", "rectangles", "expected a list" },
        { "wrong-type-material.json", "rectangles[0].material", "expected a string" },
        // Unknown, missing and dangling fields.
        { "unknown-field.json", "background", "unknown field 'background'" },
        { "unknown-field-nested.json", "rectangles[1].colour", "unknown field 'colour'" },
        { "missing-camera.json", "camera", "missing" },
        { "undefined-material.json", "rectangles[0].material", "'black' is not defined" },
        // Coordinates off the grid.
        { "negative-coordinate.json", "rectangles[0].min[0]", "-1 is outside the grid 0..15" },
        { "out-of-grid-coordinate.json", "rectangles[1].max[2]", "16 is outside the grid 0..15" },
        { "off-grid-coordinate.json", "rectangles[0].max[1]", "8.5 is not on the grid" },
        // Rectangles that are not rectangles, and none at all.
        { "no-flat-axis.json", "rectangles[1]", "min and max differ on every axis" },
        { "two-flat-axes.json", "rectangles[0]", "min equals max on 2 axes" },
        { "zero-primitives.json", "rectangles", "no primitives" },
        // Numbers that are not finite.
        { "nan-literal.json", "camera.position[1]", "JSON has no NaN or Infinity" },
        { "nan-string.json", "materials.white.diffuse[1]", "NaN and Infinity are not numbers in JSON" },
        { "infinity-literal.json", "lights[0].intensity[0]", "JSON has no NaN or Infinity" },
        { "infinity-overflow.json", "lights[0].intensity", "not a finite number" },
        // The camera inside (flat primitives: on) a primitive.
        { "camera-inside-primitive.json", "camera.position", "lies on rectangles[1]" },
        { "camera-on-edge.json", "camera.position", "lies on rectangles[1]" },
        // Image sizes.
        { "image-width-zero.json", "image.width", "0 is outside 1..8192" },
        { "image-width-million.json", "image.width", "1000000 is outside 1..8192" },
        { "image-height-overflow.json", "image.height", "fits in 32 bits" },
    };

    private string Output => _output.File("out.png");

    [Theory]
    [MemberData(nameof(Cases))]
    public void RenderRefuses(string file, string element, string problem) =>
        Outcome.Of("render", Corpus.Scene(file), "-e", "classical", "--size", "4", "-o", Output)
            .AssertBadInput(Corpus.Scene(file), element, problem, _output.Path);

    [Theory]
    [MemberData(nameof(Cases))]
    public void ScenesCheckRefuses(string file, string element, string problem) =>
        Outcome.Of("scenes", "check", Corpus.Scene(file)).AssertBadInput(Corpus.Scene(file), element, problem, null);

    [Theory]
    [MemberData(nameof(Cases))]
    public void SupersampleRefuses(string file, string element, string problem) =>
        Outcome.Of("supersample", "--scene", Corpus.Scene(file), "--size", "2", "--subpixels", "2", "-m", "mc", "-o", Output)
            .AssertBadInput(Corpus.Scene(file), element, problem, _output.Path);

    [Fact]
    public void EveryCorpusFileIsACase() =>
        Assert.Equal(Corpus.Files("Scenes", "valid.json"), Cases.Select(c => (string)c[0]).Order());

    /// <summary>The baseline passes the same harness, so the refusals above come from each file's one defect.</summary>
    [Fact]
    public void BaselineRenders()
    {
        var outcome = Outcome.Of("render", Corpus.Scene("valid.json"), "-e", "classical", "--size", "4", "-o", Output);
        Assert.True(outcome.Code == 0, outcome.Error);
        Assert.Equal(["out.png"], Directory.GetFiles(_output.Path).Select(Path.GetFileName));
        Assert.Equal(0, Outcome.Of("scenes", "check", Corpus.Scene("valid.json")).Code);
    }
}
