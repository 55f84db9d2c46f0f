// The tiled noise (GT_NOISE_TABLE) on the GPU (lavapipe, through gt-harness) against Core: the
// domain stage reads Core's 256 x 256 cell table (bound at 9) and must draw Core's float path
// vertex for vertex, at octaves fine enough to wrap the table, with and without a range origin.
// Fails (never skips) when the harness, lavapipe, glslang or gt-cli is missing: `gt setup`.
using System;
using System.IO;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class TiledNoiseGpuTests
    {
        const int Tiles = 8, Factor = 15;

        // Six octaves from 16 cells across: octave 4 spans the table's 256 cells, octave 5 wraps it
        // twice. noiseVerticesAcross 8192 keeps every octave in (the count rule would drop the fine ones).
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        const float VerticesAcross = 8192f;
        // GPU against Core float, relative to the terrain's extent (TerrainGpuTests' bound).
        const double Bound = 1e-5;

        string _work, _spirv;
        PatchGrid _grid;

        [OneTimeSetUp]
        public void BuildGridAndShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-tiled-noise");
            _grid = ReadbackRun.DemoGrid(_work, out _);
            _spirv = ReadbackRun.CompileVariants(_work, "readback+noise+noise_table");
        }

        ReadbackRun Draw(string name, TerrainRange range)
        {
            var p = ReadbackRun.UniformParams(_grid, range, RangeOrigin.For(range), Tiles, Factor, Noise, VerticesAcross);
            return ReadbackRun.Draw(Path.Combine(_work, name), _spirv, _grid, p, Noise, tiledNoise: true);
        }

        [TestCase("full", 0.0, 0.0, 1.0, 1.0)]
        [TestCase("narrow", 0.6131, 0.2217, 0.6141, 0.2227)]   // below RangeOrigin.DeepWidth: drawn from a snapped origin
        public void GpuReadbackMatchesCoreAndTheDoubleReference(string name, double c, double d, double g, double h)
        {
            ReadbackRun run = Draw(name, new TerrainRange(c, d, g, h));
            Assert.That(run.Inputs.NoiseOctaveCount(), Is.EqualTo(6f), "every octave drawn, the table wrapped");
            double extent = ReadbackRun.TerrainExtent(_grid);
            ReadbackComparison cmp = run.Compare();
            TestContext.Out.WriteLine(
                "{0}: {1} vertices, position bit-identical {2}, max |gpu - core| / extent {3:G3}, max |normal diff| {4:G3}, " +
                "max |core float - double| / extent {5:G3}", name, cmp.Vertices, cmp.PositionBitIdentical,
                cmp.MaxPosition / extent, cmp.MaxNormal, cmp.MaxReference / extent);
            Assert.That(cmp.Nan, Is.EqualTo(0), "readback slots never written");
            Assert.That(cmp.Unmatched, Is.EqualTo(0), "vertices whose tess coordinate could not be recovered");
            Assert.That(cmp.Vertices, Is.EqualTo(Tiles * Tiles * (Factor + 1) * (Factor + 1)));
            Assert.That(cmp.MaxPosition / extent, Is.LessThan(Bound), "GPU against Core float, relative to the extent");
            Assert.That(cmp.MaxNormal, Is.LessThan(1e-3), "GPU against Core float normals");
            Assert.That(cmp.MaxReference / extent, Is.LessThan(1e-5), "Core float against the double reference");

            // The same vertices against the hashed noise: the comparison tells the two noises apart, so
            // a stage that ignored its table (or a Core that ignored the keyword) would fail above.
            run.Keywords = TerrainKeywords.Noise;
            ReadbackComparison hashed = run.Compare();
            TestContext.Out.WriteLine("{0}: the tiled draw against Core's hashed noise: max |gpu - core| / extent {1:G3}", name, hashed.MaxPosition / extent);
            Assert.That(hashed.MaxPosition / extent, Is.GreaterThan(Bound), "the tiled noise is another noise than the hashed one");
        }
    }
}
