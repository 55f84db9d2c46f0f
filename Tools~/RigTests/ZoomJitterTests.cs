using System;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The deep-zoom vertex jitter table (precision.md), plain float vs the shipped path, with the
    /// rig's own measure (Tools~/dotnet/Gt/ZoomJitter.cs, gt-cli jitter). DeepZoomGpuTests compares
    /// it with the GPU.
    /// </summary>
    [TestFixture]
    public class ZoomJitterTests
    {
        static PatchGrid _grid;
        static PatchGrid Grid => _grid ??= GregoryTerrain.Tests.HardCaseGrids.Fitted();

        [TestCase(1e-2)]
        [TestCase(1e-4)]
        [TestCase(1e-6)]
        public void ShippedPathJitterStaysBelowHalfAPixel(double width)
        {
            foreach (var c in new[] { new Double2(0.5137, 0.6262), new Double2(0.4, 0.6) })
            {
                double plain = ZoomJitter.Measure(Grid, VertexPath.Plain, c, width, 800, 4, 8, 0.25, out _);
                double shipped = ZoomJitter.Measure(Grid, VertexPath.Shipped, c, width, 800, 4, 8, 0.25, out double err);
                TestContext.Out.WriteLine($"jitter width {width:G3} centre {c}: plain {plain:G3} px, shipped {shipped:G3} px (largest error {err:G3} px)");
                Assert.That(shipped, Is.LessThan(0.5));
                Assert.That(err, Is.LessThan(0.5));
                // Since the control points are stored relative to their patch (GpuLayout), the plain
                // path holds ~1 px at 1e-4; the float q (6e-8) still breaks it at 1e-6.
                if (width <= 1e-6) Assert.That(plain, Is.GreaterThan(1.0), "plain float should break down here");
            }
        }

        [TestCase(1e-2)]
        [TestCase(1e-4)]
        [TestCase(1e-6)]
        public void ShippedPathJitterWithNoiseStaysBelowHalfAPixel(double width)
        {
            // 6 octaves of amplitude 0.004 (the rig's noise); the shipped path adds the noise as
            // p(q) - p(O) from precise lattice steps plus p(O) in double (OctaveNoise.Relative).
            var noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
            foreach (var c in new[] { new Double2(0.5137, 0.6262), new Double2(0.4, 0.6) })
            {
                double plain = ZoomJitter.Measure(Grid, VertexPath.Plain, c, width, 800, 4, 8, 0.25, out _, noise);
                double shipped = ZoomJitter.Measure(Grid, VertexPath.Shipped, c, width, 800, 4, 8, 0.25, out double err, noise);
                TestContext.Out.WriteLine($"jitter with noise width {width:G3} centre {c}: plain {plain:G3} px, shipped {shipped:G3} px (largest error {err:G3} px)");
                Assert.That(shipped, Is.LessThan(0.5));
                Assert.That(err, Is.LessThan(0.5));
                // Since the control points are stored relative to their patch (GpuLayout), the plain
                // path holds ~1 px at 1e-4; the float q (6e-8) still breaks it at 1e-6.
                if (width <= 1e-6) Assert.That(plain, Is.GreaterThan(1.0), "plain float should break down here");
            }
        }

        [Test]
        public void MeasureWithBadWidthNamesTheWidth()
        {
            var e = Assert.Throws<ArgumentException>(() => ZoomJitter.Measure(GregoryTerrain.Tests.HardCaseGrids.Fitted(3, 3, 2, 17), VertexPath.Shipped,
                new Double2(0.5, 0.5), 2.0, 800, 4, 8, 0.25, out _));
            Assert.That(e.Message, Does.Contain("width").And.Contain("2"));
        }
    }
}
