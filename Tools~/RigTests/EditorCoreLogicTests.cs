using System;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Core logic behind the editor tools' fixes of issue 36 (the Patch Grid window, the Scene-view
    /// handles). Tested with the rig rather than in Tests/Core, which ships: the package is at its size limit.
    /// </summary>
    [TestFixture]
    public class EditorCoreLogicTests
    {
        static double Dist(Double3 a, Double3 b) => GMath.length(a - b);

        /// <summary>
        /// A RAW file comes out south row first (the terrain's y = 0 edge): .hgt files are stored north
        /// to south and are flipped by default; other RAW files are read as Unity's Import Raw reads them
        /// with Flip Vertically off (row 0 at the south edge); either can be forced.
        /// </summary>
        [Test]
        public void RawRowsComeOutSouthFirst()
        {
            // 2 x 3 samples, unsigned 16-bit little-endian: rows 0 (1, 2), 1 (3, 4), 2 (5, 6) as stored.
            byte[] bytes = { 1, 0, 2, 0, 3, 0, 4, 0, 5, 0, 6, 0 };
            double[] Read(string name, RawRowOrder order)
            {
                int w = 2, h = 0;
                double[] z = RawHeightmap.ReadSouthFirst(name, bytes, RawSampleFormat.UInt16LittleEndian, order, ref w, ref h);
                Assert.That((w, h), Is.EqualTo((2, 3)));
                return z;
            }
            var stored = new double[] { 1, 2, 3, 4, 5, 6 };
            var flipped = new double[] { 5, 6, 3, 4, 1, 2 };
            Assert.That(Read("n.hgt", RawRowOrder.ByFileType), Is.EqualTo(flipped), ".hgt: first row north");
            Assert.That(Read("N48E009.HGT", RawRowOrder.ByFileType), Is.EqualTo(flipped), "extension in any case");
            Assert.That(Read("t.raw", RawRowOrder.ByFileType), Is.EqualTo(stored), "RAW: as Unity's Import Raw, Flip Vertically off");
            Assert.That(Read("t.raw", RawRowOrder.NorthFirst), Is.EqualTo(flipped));
            Assert.That(Read("n.hgt", RawRowOrder.SouthFirst), Is.EqualTo(stored));
            var ex = Assert.Throws<ArgumentException>(() => Read("t.raw", (RawRowOrder)7));
            Assert.That(ex.Message, Does.Contain("t.raw").And.Contain("order = 7"));
        }

        /// <summary>
        /// The Scene view's control points and handles (GregoryTerrainRendererEditor, the sculpt tool's
        /// outline) go through <see cref="TerrainWorldFrame.TerrainToWorld"/> and back: with the Walk
        /// sample's frame (Transform at (-10000, 0, -10000), 20 km across, 3000 m per height unit) and a
        /// floating-origin shift, a control point is drawn where the draw matrices put the surface's
        /// point, and a 1 m handle drag moves it 1 m, not 20 km (the Transform's matrix alone).
        /// </summary>
        [Test]
        public void ControlPointsMapToTheWorldAsTheDrawMatricesDo()
        {
            Float4x4 l = Float4x4.FromRows(1, 0, 0, -10000, 0, 1, 0, 0, 0, 0, 1, -10000, 0, 0, 0, 1);
            var f = new TerrainWorldFrame(l, new Double2(20000, 20000), 3000, new Double3(125.5, -3, -77.25));
            var cp = new Double3(0.75, 0.25, 0.1);   // terrain x, y, height
            Double3 w = f.TerrainToWorld(cp);
            Assert.That(w.x, Is.EqualTo(-10000 + 0.75 * 20000 + 125.5).Within(1e-9));
            Assert.That(w.y, Is.EqualTo(0.1 * 3000 - 3).Within(1e-9));
            Assert.That(w.z, Is.EqualTo(-10000 + 0.25 * 20000 - 77.25).Within(1e-9), "terrain y is world +Z");
            // The draw matrices (deep-zoom offset t near the point) put the same object point there.
            Double3 t = TerrainVertex.TerrainToObject(new Double3(0.7, 0.3, 0.05));
            f.DrawMatrices(t, out Float4x4 m, out _);
            Double3 o = TerrainVertex.TerrainToObject(cp) - t;
            Float4 drawn = m * new Float4((float)o.x, (float)o.y, (float)o.z, 1f);
            Assert.That(Dist(new Double3(drawn.x, drawn.y, drawn.z), w), Is.LessThan(2e-3), "float draw matrix at 1 km from its origin");
            // A 1 m drag along each world axis moves the control point 1 m in the world.
            foreach (var d in new[] { new Double3(1, 0, 0), new Double3(0, 1, 0), new Double3(0, 0, 1) })
            {
                Double3 moved = f.WorldToTerrain(w + d);
                Assert.That(Dist(f.TerrainToWorld(moved), w + d), Is.LessThan(1e-9));
                Assert.That(Dist(moved, cp), Is.EqualTo(d.y != 0 ? 1.0 / 3000 : 1.0 / 20000).Within(1e-12), $"terrain units moved by 1 m along {d}");
            }
        }
    }
}
