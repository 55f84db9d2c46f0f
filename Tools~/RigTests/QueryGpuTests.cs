// The CPU queries (Core's TerrainSurfaceQuery, what GregoryTerrainRenderer.SampleHeight answers)
// against the GPU's own vertices (lavapipe, through gt-harness): every read-back vertex's height
// against the query at the GPU's global point, with the noise at every octave on both sides. Fails
// (never skips) when the harness, lavapipe, glslang or gt-cli is missing: `gt setup` provides them.
using System;
using System.IO;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class QueryGpuTests
    {
        const int Tiles = 8, Factor = 15;
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 8);

        [TestCase(false)]
        [TestCase(true)]
        public void SampleHeightMatchesTheGpuVerticesAtFullDetail(bool noise)
        {
            string work = ReadbackRun.PrepareWork("rigtests-query" + (noise ? "-noise" : ""));
            PatchGrid grid = ReadbackRun.DemoGrid(work, out _);
            string spirv = ReadbackRun.CompileVariants(work, "readback", "readback+noise");
            var query = new TerrainSurfaceQuery(grid, noise ? Noise : (NoiseSettings?)null);
            double worst = 0, worstFloat = 0;
            int vertices = 0;
            foreach (var range in new[] { TerrainRange.full, new TerrainRange(0.3, 0.15, 0.8, 0.65) })
            {
                // Origin 0: the GPU outputs absolute heights. A huge vertex budget for the octave count
                // makes the GPU evaluate every octave, as it does where the range is narrow enough.
                var p = ReadbackRun.UniformParams(grid, range, RangeOrigin.zero, Tiles, Factor, Noise, 1e9f);
                ReadbackRun run = ReadbackRun.Draw(Path.Combine(work, range.c.ToString("R")), spirv, grid, p, noise ? Noise : (NoiseSettings?)null);
                if (noise) Assert.That(run.Inputs.NoiseOctaveCount(), Is.EqualTo((float)Noise.octaves));
                float[] v = run.Readback;
                for (int k = 0; k < run.VertexCount; k++)
                {
                    int o = 12 * k;
                    // Readback: (position.xyz, 1) in object space (x, height, y), (normal, 0), (q.xy, u, v).
                    double qx = v[o + 8], qy = v[o + 9];
                    double h = query.SampleHeight(qx, qy);
                    worst = Math.Max(worst, Math.Abs(v[o + 1] - h));
                    TerrainVertexOutput f = TerrainVertex.EvaluateAt(run.Inputs, TerrainPoint.FromFloat(new Float2(v[o + 8], v[o + 9])), run.Keywords);
                    worstFloat = Math.Max(worstFloat, Math.Abs(f.position.z - h));
                    vertices++;
                }
            }
            TestContext.WriteLine($"noise {(noise ? "on (8 octaves)" : "off")}: {vertices} GPU vertices, largest |GPU height - SampleHeight| {worst:G3}, Core float path {worstFloat:G3} (terrain units)");
            Assert.That(vertices, Is.EqualTo(2 * Tiles * Tiles * (Factor + 1) * (Factor + 1)));
            // The GPU rounds to float (heights ~0.1, control points and noise sums): a few ulps.
            Assert.That(worst, Is.LessThan(2e-7));
        }
    }
}
