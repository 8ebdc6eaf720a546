using System.Diagnostics;
using System.Text.Json;

namespace QuantumRayTracing.Tests.Output;

/// <summary>
/// Decodes a PNG file with Node.js, using only its built-in zlib and Buffer: a second decoder whose inflate
/// (Node's bundled zlib) and PNG parsing share nothing with .NET or with <see cref="PngTestDecoder"/>.
/// </summary>
internal static class NodePngDecoder
{
    /// <summary>What Node read: the IHDR size and every pixel, row-major RGB.</summary>
    public sealed record Result(int Width, int Height, byte[] Rgb);

    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(30);

    // process.argv[1] is the PNG path (with `node -e`, there is no script path in argv).
    private const string Script = """
        const fs = require('fs'), zlib = require('zlib');
        const png = fs.readFileSync(process.argv[1]);
        if (!png.subarray(0, 8).equals(Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]))) throw new Error('bad signature');
        let at = 8, width = 0, height = 0, ended = false;
        const idat = [];
        while (at < png.length && !ended) {
          const length = png.readUInt32BE(at), type = png.toString('latin1', at + 4, at + 8), data = png.subarray(at + 8, at + 8 + length);
          if (type === 'IHDR') {
            width = data.readUInt32BE(0); height = data.readUInt32BE(4);
            if (data[8] !== 8 || data[9] !== 2 || data[10] !== 0 || data[11] !== 0 || data[12] !== 0) throw new Error('unsupported IHDR');
          } else if (type === 'IDAT') idat.push(data);
          else if (type === 'IEND') ended = true;
          at += 12 + length;
        }
        if (!ended || at !== png.length) throw new Error('missing IEND or trailing bytes');
        const raw = zlib.inflateSync(Buffer.concat(idat)), stride = width * 3;
        if (raw.length !== height * (stride + 1)) throw new Error('inflated ' + raw.length + ' bytes');
        const rgb = Buffer.alloc(height * stride);
        for (let y = 0; y < height; y++) {
          const filter = raw[y * (stride + 1)];
          for (let i = 0; i < stride; i++) {
            const a = i >= 3 ? rgb[y * stride + i - 3] : 0, b = y > 0 ? rgb[(y - 1) * stride + i] : 0;
            const c = i >= 3 && y > 0 ? rgb[(y - 1) * stride + i - 3] : 0;
            const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
            const predictor = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][filter];
            if (predictor === undefined) throw new Error('filter type ' + filter);
            rgb[y * stride + i] = (raw[y * (stride + 1) + 1 + i] + predictor) & 0xff;
          }
        }
        console.log(JSON.stringify({ width, height, rgb: rgb.toString('hex') }));
        """;

    /// <summary>Runs Node on <paramref name="path"/>; throws with Node's error output if it fails or takes too long.</summary>
    public static async Task<Result> DecodeAsync(string path)
    {
        var start = new ProcessStartInfo("node")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        start.ArgumentList.Add("-e");
        start.ArgumentList.Add(Script);
        start.ArgumentList.Add(path);

        using var process = Process.Start(start) ?? throw new InvalidOperationException("could not start node");
        using var timeout = new CancellationTokenSource(Timeout);
        // Both streams are drained while waiting, so a chatty process cannot block on a full pipe.
        var output = process.StandardOutput.ReadToEndAsync(timeout.Token);
        var error = process.StandardError.ReadToEndAsync(timeout.Token);
        try
        {
            await process.WaitForExitAsync(timeout.Token);
        }
        catch (OperationCanceledException)
        {
            process.Kill(entireProcessTree: true);
            throw new TimeoutException($"node did not decode {path} within {Timeout.TotalSeconds} s");
        }
        var (stdout, stderr) = (await output, await error);
        if (process.ExitCode != 0)
            throw new InvalidOperationException($"node exited with {process.ExitCode}: {stderr}");

        using var json = JsonDocument.Parse(stdout);
        var root = json.RootElement;
        return new Result(
            root.GetProperty("width").GetInt32(),
            root.GetProperty("height").GetInt32(),
            Convert.FromHexString(root.GetProperty("rgb").GetString()!));
    }
}
