using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class TerrainWorldFrameTests
    {
        // A Transform at (1000, 20, -3000) turned 30 degrees about the up axis (no scale), as Unity gives
        // its localToWorld (float entries).
        static TerrainWorldFrame Frame(Double2 size, double height, Double3 offset)
        {
            float c = (float)Math.Cos(Math.PI / 6), s = (float)Math.Sin(Math.PI / 6);
            Float4x4 l = Float4x4.FromRows(c, 0, s, 1000, 0, 1, 0, 20, -s, 0, c, -3000, 0, 0, 0, 1);
            return new TerrainWorldFrame(l, size, height, offset);
        }

        static double Dist(Double3 a, Double3 b) => GMath.length(a - b);

        [Test]
        public void SizeAndHeightScaleCarryMetres()
        {
            // 1,000 km across, heights 8,848 m per terrain unit.
            TerrainWorldFrame f = Frame(new Double2(1e6, 1e6), 8848, Double3.zero);
            Double3 a = f.ObjectToWorld(new Double3(0, 0, 0)), b = f.ObjectToWorld(new Double3(0.5, 0, 0));
            // (the float rotation's columns are unit length to 1e-8: 7 mm over 500 km, in the Transform itself)
            Assert.That(Dist(a, b), Is.EqualTo(5e5).Within(0.05));
            Double3 up = f.ObjectToWorld(new Double3(0, 1, 0));
            Assert.That(up.y - a.y, Is.EqualTo(8848).Within(1e-9));
            Assert.That(f.ObjectScale.x, Is.EqualTo(1e6).Within(1e-1));
            Assert.That(f.ObjectScale.y, Is.EqualTo(8848).Within(1e-3));
            // Round trip, in double.
            var o = new Double3(0.1234567891, 0.004, 0.87654321);
            Assert.That(Dist(f.WorldToObject(f.ObjectToWorld(o)), o), Is.LessThan(1e-12));
            // A slope of 1 in object units is one of heightScale / size in world: the normal tilts accordingly.
            Double3 n = f.NormalToWorld(GMath.normalize(new Double3(-1, 1, 0)));
            Double3 tangent = f.ObjectToWorld(new Double3(1, 1, 0)) - f.ObjectToWorld(Double3.zero);
            Assert.That(Math.Abs(GMath.dot(n, tangent)) / GMath.length(tangent), Is.LessThan(1e-7));
        }

        [Test]
        public void ShiftingTheOriginMovesNothingRelativeToTheCamera()
        {
            TerrainWorldFrame f = Frame(new Double2(1e6, 1e6), 8848, new Double3(0.25, 0, -0.5));
            var camera = new Double3(312345.678, 1500.25, -45678.9);
            var delta = new Double3(-312000, -1000, 45000);   // the application recentres near the camera
            TerrainWorldFrame g = f.Shifted(delta);
            foreach (var o in new[] { new Double3(0.3, 0.01, 0.05), new Double3(0.31, 0.02, 0.049), new Double3(0.9, 0, 0.9) })
            {
                Double3 before = f.ObjectToWorld(o) - camera, after = g.ObjectToWorld(o) - (camera + delta);
                Assert.That(Dist(before, after), Is.LessThan(1e-9), $"object {o}");
                Assert.That(Dist(g.WorldToObject(g.ObjectToWorld(o)), o), Is.LessThan(1e-12));
            }
            // The draw matrix's translation is formed in double and rounded once: it moved by delta exactly
            // as far as float holds it, so a vertex 1 m from the camera stays within float's step there.
            Double3 t = f.WorldToObject(camera + new Double3(1, -2, 3));   // the deep-zoom output offset S(O) near the camera, object space
            f.DrawMatrices(t, out Float4x4 m0, out Float4x4 w0);
            g.DrawMatrices(t, out Float4x4 m1, out _);
            Double3 c0 = new Double3(m0.c3.x, m0.c3.y, m0.c3.z) - camera, c1 = new Double3(m1.c3.x, m1.c3.y, m1.c3.z) - (camera + delta);
            Assert.That(Dist(c0, f.ObjectToWorld(t) - camera), Is.LessThan(0.02));     // float at 3e5 m: 1.6 cm steps
            Assert.That(Dist(c1, g.ObjectToWorld(t) - (camera + delta)), Is.LessThan(1e-4));   // near the camera: 0.03 mm steps
            // The inverse undoes the draw matrix.
            Float4 back = w0 * (m0 * new Float4(1e-3f, 2e-3f, -1e-3f, 1f));
            Assert.That(back.x, Is.EqualTo(1e-3f).Within(0.05f));
        }

        [Test]
        public void BadScaleOrOffsetIsRefusedNamingTheField()
        {
            var e = Assert.Throws<ArgumentException>(() => Frame(new Double2(0, 1), 1, Double3.zero));
            Assert.That(e.Message, Does.Contain("terrainSize").And.Contain("0"));
            e = Assert.Throws<ArgumentException>(() => Frame(new Double2(1, 1), double.NaN, Double3.zero));
            Assert.That(e.Message, Does.Contain("heightScale").And.Contain("NaN"));
            e = Assert.Throws<ArgumentException>(() => Frame(new Double2(1, 1), 1, Double3.zero).Shifted(new Double3(double.PositiveInfinity, 0, 0)));
            Assert.That(e.Message, Does.Contain("delta"));
            e = Assert.Throws<ArgumentException>(() => new TerrainWorldFrame(Float4x4.FromRows(1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1), new Double2(1, 1), 1, Double3.zero));
            Assert.That(e.Message, Does.Contain("localToWorld").And.Contain("invertible"));
        }
    }
}
