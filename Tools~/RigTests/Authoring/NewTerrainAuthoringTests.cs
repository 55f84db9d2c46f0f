using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The terrain GameObject &gt; 3D Object &gt; Gregory Terrain makes, through the same Core
    /// operations: its size in metres as typed (Transform scale 1), its control-point spacing under
    /// the sculpt brush's default radius, and a stroke at that radius raising the surface.
    /// </summary>
    [TestFixture]
    public class NewTerrainAuthoringTests
    {
        static TerrainWorldFrame MenuFrame() => new TerrainWorldFrame(Float4x4.identity,
            new Double2(NewTerrainAuthoring.SizeMetres, NewTerrainAuthoring.SizeMetres), NewTerrainAuthoring.HeightMetres, Double3.zero);

        [Test]
        public void MenuTerrainSpansItsSizeInMetres()
        {
            Double3 corner = MenuFrame().ObjectToWorld(new Double3(1, 1, 1));   // object (x, height, y)
            Assert.That(corner.x, Is.EqualTo(1000.0).Within(1e-9));
            Assert.That(corner.y, Is.EqualTo(600.0).Within(1e-9));
            Assert.That(corner.z, Is.EqualTo(1000.0).Within(1e-9));
        }

        [Test]
        public void MenuGridsControlPointsAreCloserThanTheDefaultBrush()
        {
            PatchGrid grid = NewTerrainAuthoring.CreateGrid();
            double spacing = NewTerrainAuthoring.ControlPointSpacing(grid.XLines, grid.YLines, NewTerrainAuthoring.SizeMetres, NewTerrainAuthoring.SizeMetres);
            TestContext.Out.WriteLine($"menu terrain: {grid.Columns} x {grid.Rows} patches, control points {spacing:G4} m apart");
            Assert.That(spacing, Is.EqualTo(1000.0 / 192.0).Within(1e-9), "metres between control points");
            Assert.That(spacing, Is.LessThan(NewTerrainAuthoring.DefaultBrushMetres / 4), "the default brush spans several control points");
        }

        [Test]
        public void StrokeAtTheDefaultBrushRaisesTheMenuTerrain()
        {
            PatchGrid grid = NewTerrainAuthoring.CreateGrid();
            Double3 scale = MenuFrame().ObjectScale;   // metres per object unit, as the sculpt tool divides by
            double radius = NewTerrainAuthoring.DefaultBrushMetres / scale.x, raise = 1.0 / scale.y;
            // A stroke 200 m long in the middle: a dab every quarter radius, 1 m each (the tool's defaults).
            for (double x = 0.4; x <= 0.6 + 1e-12; x += radius / 4)
                PatchBrush.Apply(grid, new BrushDab(BrushMode.Raise, x, 0.5, radius, raise)).ApplyTo(grid);
            double middle = ResampleAuthoring.Height(grid, 0.5, 0.5) * scale.y;
            double far = ResampleAuthoring.Height(grid, 0.1, 0.1) * scale.y;
            TestContext.Out.WriteLine($"stroke of {NewTerrainAuthoring.DefaultBrushMetres} m dabs, 1 m each, every quarter radius over 200 m: ground under it raised {middle:G4} m, 400 m away {far} m");
            Assert.That(middle, Is.GreaterThan(2.0), "metres the stroke raised the ground under it");
            Assert.That(far, Is.EqualTo(0.0), "ground far from the stroke");
        }

        [Test]
        public void SpacingOfAnUnevenGridIsItsWidestInterval()
        {
            PatchGrid grid = PatchGrid.CreateFlat(2, 1, new[] { 0, 0.75, 1.0 }, PatchGrid.UniformLines(1));
            Assert.That(NewTerrainAuthoring.ControlPointSpacing(grid.XLines, grid.YLines, 300, 30), Is.EqualTo(75.0).Within(1e-9));
            Assert.That(NewTerrainAuthoring.ClampBrushRadius(10, 75), Is.EqualTo(75.0));
            Assert.That(NewTerrainAuthoring.ClampBrushRadius(90, 75), Is.EqualTo(90.0));
            var e = Assert.Throws<ArgumentException>(() => NewTerrainAuthoring.ControlPointSpacing(grid.XLines, grid.YLines, 0, 30));
            Assert.That(e.Message, Does.Contain("sizeXMetres = 0"));
        }
    }
}
