using System;
using System.Buffers.Binary;
using System.IO;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// A real SRTM tile read as the Patch Grid window reads a RAW file (RawHeightmap.ReadSouthFirst with
    /// the window's default row order, then the fitter): what is north in the file is north in the
    /// terrain. SRTM stores rows north to south (its format; Tools~/RigTests/Data/dem/README.md), so the
    /// file's first row must become the terrain's y = 1 edge, which the renderer's world frame puts at
    /// world +Z. The crop is N48E009_east.hgt (rows 480..720 of N48E009.hgt in /work/shared/dem, no voids).
    /// </summary>
    [TestFixture]
    public class SrtmOrientationTests
    {
        [Test]
        public void NorthInTheFileIsNorthInTheTerrain()
        {
            string name = DemFitTests.West;
            byte[] bytes = File.ReadAllBytes(PackageRoot.Combine("Tools~", "RigTests", "Data", "dem", name));
            int w = 0, h = 0;
            double[] z = RawHeightmap.ReadSouthFirst(name, bytes, RawSampleFormat.Int16BigEndian, RawRowOrder.ByFileType, ref w, ref h, RawHeightmap.SrtmVoid);
            Assert.That(HeightmapVoids.Fill(z, w, h), Is.EqualTo(0), "this crop has no voids");
            HeightmapFit fit = HeightmapFitter.Fit(z, w, h, 16, 16);

            // The terrain's y = 1 edge is the world's +Z side (identity Transform, the crop's size in metres).
            var frame = new TerrainWorldFrame(Float4x4.FromRows(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
                new Double2((w - 1) * 61.2, (h - 1) * 92.6), 1.0, Double3.zero);
            Assert.That(frame.TerrainToWorld(new Double3(0.5, 1, 0)).z, Is.GreaterThan(frame.TerrainToWorld(new Double3(0.5, 0, 0)).z));

            // The fitted surface along that edge against the file's first row (the north edge, read
            // straight from the bytes: big-endian signed 16-bit metres) and its last row (the south edge).
            double north = EdgeRms(fit.Grid, 1.0, c => FileSample(bytes, w, 0, c), w);
            double south = EdgeRms(fit.Grid, 1.0, c => FileSample(bytes, w, h - 1, c), w);
            TestContext.WriteLine($"{name}: {w} x {h}; fitted +Z edge vs file row 0 (north) RMS {north:F2} m, vs row {h - 1} (south) RMS {south:F2} m; fit RMS {fit.RmsError:F2} m");
            Assert.That(north, Is.LessThan(3 * fit.RmsError), "the +Z edge follows the file's first row");
            Assert.That(south, Is.GreaterThan(10 * north), "and not the last: the terrain is not mirrored north-south");
        }

        static double FileSample(byte[] bytes, int width, int row, int column) =>
            BinaryPrimitives.ReadInt16BigEndian(bytes.AsSpan(2 * (row * width + column), 2));

        /// <summary>RMS over the sample columns of (surface height at terrain y - expected sample).</summary>
        static double EdgeRms(PatchGrid g, double y, Func<int, double> expected, int width)
        {
            double s2 = 0;
            for (int c = 0; c < width; c++)
            {
                double x = (double)c / (width - 1);
                int p = g.FindPatch(x, y);
                Region r = g.RegionOf(p);
                double e = GregoryEval.Position(g.Patches[p].Points, (x - r.a) / r.Width, (y - r.b) / r.Height).z - expected(c);
                s2 += e * e;
            }
            return Math.Sqrt(s2 / width);
        }
    }
}
