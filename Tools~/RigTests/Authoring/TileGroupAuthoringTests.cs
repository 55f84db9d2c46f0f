using System;
using System.Collections.Generic;
using NUnit.Framework;
using static GregoryTerrain.Tests.AuthoringGrids;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// TileGroupAuthoring: Unity Terrain tiles, given in any order, are arranged by position and
    /// converted into one grid that is G1 and watertight across the seams; tiles of another size,
    /// apart from the others, on top of another or short of a rectangle are refused by name.
    /// </summary>
    [TestFixture]
    public class TileGroupAuthoringTests
    {
        const int Resolution = 33;
        const double Size = 500;

        /// <summary>Tile (i, j) of a 3 x 2 group over F's unit square, sharing its edge samples with its neighbours.</summary>
        static TerrainTile Tile(int i, int j, string name = null, double size = Size)
        {
            var z = new double[Resolution * Resolution];
            for (int r = 0; r < Resolution; r++)
                for (int c = 0; c < Resolution; c++)
                    z[r * Resolution + c] = 0.5 + F((i + c / (Resolution - 1.0)) / 3.0, (j + r / (Resolution - 1.0)) / 2.0);
            return new TerrainTile(name ?? $"Terrain {i},{j}", 100 + i * size, -50 + j * size, size, 600, size, Resolution, z);
        }

        static List<TerrainTile> Group() => new List<TerrainTile> { Tile(2, 1), Tile(0, 0), Tile(1, 1), Tile(2, 0), Tile(0, 1), Tile(1, 0) };

        [Test]
        public void TilesJoinIntoOneSeamlessGrid()
        {
            TerrainTile[,] tiles = TileGroupAuthoring.Arrange(Group());
            Assert.That(tiles.GetLength(0), Is.EqualTo(3));
            Assert.That(tiles.GetLength(1), Is.EqualTo(2));
            Assert.That(tiles[2, 1].Name, Is.EqualTo("Terrain 2,1"));
            PatchGrid joined = TileGroupAuthoring.FitAndJoin(tiles, 4, 4, out double max, out double rms);
            Assert.That(joined.Columns, Is.EqualTo(12));
            Assert.That(joined.Rows, Is.EqualTo(8));
            Assert.That(ContinuityMeasure.MaxPositionGap(joined), Is.LessThan(1e-12), "largest gap across any shared edge (height units)");
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(joined), Is.LessThan(1e-6), "largest normal angle across any shared edge, seams included (degrees)");
            TestContext.Out.WriteLine($"3 x 2 tiles of 33 x 33 samples, 4 x 4 patches each: normal angle across edges {ContinuityMeasure.MaxNormalAngleDegrees(joined):G3} deg, gap {ContinuityMeasure.MaxPositionGap(joined):G3}, max error {max:G3}, RMS {rms:G3}");
            Assert.That(max, Is.LessThan(1e-3), "max error against the tiles' samples");
            Assert.That(rms, Is.LessThanOrEqualTo(max));
            // Across the seams the surface is the group's: off-sample points near x = 1/3 and y = 1/2.
            for (int k = 0; k <= 20; k++)
            {
                double t = k / 20.0;
                Assert.That(ResampleAuthoring.Height(joined, 1.0 / 3, t), Is.EqualTo(0.5 + F(1.0 / 3, t)).Within(2e-3));
                Assert.That(ResampleAuthoring.Height(joined, t, 0.5), Is.EqualTo(0.5 + F(t, 0.5)).Within(2e-3));
            }
        }

        [Test]
        public void TileOfAnotherSizeIsRefusedByName()
        {
            var tiles = Group();
            tiles[3] = Tile(2, 0, "Odd one", 400);
            var e = Assert.Throws<ArgumentException>(() => TileGroupAuthoring.Arrange(tiles));
            Assert.That(e.Message, Does.Contain("'Odd one' is 400 x 600 x 400 m"));
        }

        [Test]
        public void TileApartFromTheOthersIsRefusedByName()
        {
            var tiles = Group();
            var t = tiles[0];
            tiles[0] = new TerrainTile("Drifted", t.X + 10, t.Z, t.SizeX, t.SizeY, t.SizeZ, t.Resolution, t.Heights);
            var e = Assert.Throws<ArgumentException>(() => TileGroupAuthoring.Arrange(tiles));
            Assert.That(e.Message, Does.Contain("'Drifted' at (1110, 450) is not edge to edge"));
        }

        [Test]
        public void HoleOrOverlapIsRefused()
        {
            var tiles = Group();
            tiles.RemoveAt(2);   // Terrain 1,1
            var e = Assert.Throws<ArgumentException>(() => TileGroupAuthoring.Arrange(tiles));
            Assert.That(e.Message, Does.Contain("no tile at column 1, row 1 (600, 450) of the 3 x 2 group"));
            tiles = Group();
            tiles.Add(Tile(1, 1, "Copy"));
            e = Assert.Throws<ArgumentException>(() => TileGroupAuthoring.Arrange(tiles));
            Assert.That(e.Message, Does.Contain("'Copy' lies on tile 'Terrain 1,1'"));
        }
    }
}
