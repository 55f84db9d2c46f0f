using System;
using NUnit.Framework;
using UnityEngine;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The renderer's world-space queries through its Transform (Edit Mode and Play Mode): on a planar
    /// grid (Gregory patches reproduce a plane exactly) the height, the normal and a ray's hit are
    /// known in closed form. No noise: the test material has no GT_NOISE.
    /// </summary>
    [EditorOnly]   // draws with the package's shader, loaded through the AssetDatabase (TestTerrain)
    public class RendererQueryTests
    {
        TestTerrain _t;
        GregoryTerrainRenderer _r;
        // The plane z = A + B x + C y in terrain units; the Transform below maps it to world space.
        const double A = 0.02, B = 0.05, C = -0.03;
        static readonly Vector3 Position = new Vector3(10f, 5f, -3f);
        static readonly Vector3 Scale = new Vector3(1000f, 200f, 1000f);

        [SetUp]
        public void SetUp()
        {
            _t = new TestTerrain();
            PatchGrid grid = PatchGrid.CreateFlat(2, 2);
            foreach (GregoryPatch p in grid.Patches)
                for (int s = 0; s < GregoryPatch.SlotCount; s++)
                    p[s] = new Double3(p[s].x, p[s].y, A + B * p[s].x + C * p[s].y);
            _t.Grid.SetGrid(grid);
            _r = _t.Renderer("terrain");
            _r.transform.position = Position;
            _r.transform.localScale = Scale;
        }

        [TearDown] public void TearDown() => _t.Dispose();

        static float WorldHeight(double x, double y) => (float)(Position.y + Scale.y * (A + B * x + C * y));
        static Vector3 World(double x, double y, float height) => new Vector3((float)(Position.x + Scale.x * x), height, (float)(Position.z + Scale.z * y));

        [Test]
        public void SampleHeightAndNormalFollowTheTransform()
        {
            foreach (var (x, y) in new[] { (0.3, 0.6), (0.5, 0.5), (0.01, 0.99) })
            {
                Assert.That(_r.SampleHeight(World(x, y, 1e4f)), Is.EqualTo(WorldHeight(x, y)).Within(1e-3f), $"height at ({x}, {y})");
                // World normal of y = P.y + Sy (A + B x' + C y') with x' = (X - P.x) / Sx, y' = (Z - P.z) / Sz.
                Vector3 n = _r.SampleNormal(World(x, y, -50f));
                double nx = -Scale.y * B / Scale.x, nz = -Scale.y * C / Scale.z, len = Math.Sqrt(nx * nx + 1 + nz * nz);
                Assert.That(n.x, Is.EqualTo((float)(nx / len)).Within(1e-5f));
                Assert.That(n.y, Is.EqualTo((float)(1 / len)).Within(1e-5f));
                Assert.That(n.z, Is.EqualTo((float)(nz / len)).Within(1e-5f));
            }
            Assert.That(float.IsNaN(_r.SampleHeight(World(1.5, 0.5, 0f))), Is.True, "off the terrain");
            Vector3[] points = { World(0.3, 0.6, 0f), World(-1, 0, 0f), World(0.7, 0.2, 99f) };
            var heights = new float[3];
            _r.SampleHeights(points, heights);
            Assert.That(heights[0], Is.EqualTo(WorldHeight(0.3, 0.6)).Within(1e-3f));
            Assert.That(float.IsNaN(heights[1]), Is.True);
            Assert.That(heights[2], Is.EqualTo(WorldHeight(0.7, 0.2)).Within(1e-3f));
        }

        [Test]
        public void RaycastHitsThePlaneFromAboveOnly()
        {
            float h = WorldHeight(0.4, 0.4);
            Vector3 above = World(0.4, 0.4, h + 30f);
            Assert.That(_r.Raycast(new Ray { origin = above, direction = new Vector3(0f, -1f, 0f) }, 100f, out Vector3 p, out Vector3 n, out float d), Is.True);
            Assert.That(d, Is.EqualTo(30f).Within(1e-3f));
            Assert.That(p.y, Is.EqualTo(h).Within(1e-3f));
            Assert.That(n.y, Is.GreaterThan(0.99f));
            Assert.That(_r.Raycast(new Ray { origin = above, direction = new Vector3(0f, -1f, 0f) }, 29f, out _, out _, out _), Is.False, "too short");
            Assert.That(_r.Raycast(new Ray { origin = World(0.4, 0.4, h - 1f), direction = new Vector3(0f, -1f, 0f) }, 100f, out _, out _, out _), Is.False, "from below");
        }

        [Test]
        public void QueryIsRebuiltWhenTheNoiseIsTiledOrNot()
        {
            _t.Asset.EnableKeyword(ShaderKeywords.Noise);
            _t.Asset.DisableKeyword(ShaderKeywords.NoiseTable);
            TerrainSurfaceQuery hashed = _r.SurfaceQuery;
            Assert.That(hashed, Is.Not.Null);
            Assert.That(_r.SurfaceQuery, Is.SameAs(hashed), "nothing changed: the same query");
            _t.Asset.EnableKeyword(ShaderKeywords.NoiseTable);   // tiled noise is another surface
            TerrainSurfaceQuery tiled = _r.SurfaceQuery;
            Assert.That(tiled, Is.Not.SameAs(hashed));
            Assert.That(_r.SurfaceQuery, Is.SameAs(tiled));
            _t.Asset.DisableKeyword(ShaderKeywords.NoiseTable);
            Assert.That(_r.SurfaceQuery, Is.Not.SameAs(tiled));
        }
    }
}
