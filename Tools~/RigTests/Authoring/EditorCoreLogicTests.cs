using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using GregoryTerrain.Tests;

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
        // ---- Sculpting at the cost of the patches changed (PatchChangeLog, ValidatePatches, PackPatchRecord, WithPatches) ----

        /// <summary>A grid held as the asset holds it (blocks) with its log, edited by brush dabs as the sculpt tool does.</summary>
        sealed class EditedGrid
        {
            public readonly PatchGrid Core;        // the sculpt tool's own copy, written in place
            public readonly double[][] Blocks;
            public readonly PatchChangeLog Log = new PatchChangeLog();
            public int Version = 1;

            public EditedGrid(PatchGrid grid)
            {
                Core = grid.Clone();
                Blocks = PatchGridBlocks.FromGrid(grid);
                Log.Restart(Version, grid.PatchCount);
            }

            public PatchEdit Dab(double x, double y, double radius, double strength)
            {
                PatchEdit edit = PatchBrush.Apply(Core, new BrushDab(BrushMode.Raise, x, y, radius, strength));
                for (int k = 0; k < edit.Patches.Length; k++) PatchGridBlocks.SetPatch(Blocks, edit.Patches[k], edit.Values[k]);
                edit.ApplyTo(Core);
                Log.Add(++Version, edit.Patches);
                return edit;
            }
        }

        [Test]
        public void AReaderCatchesUpOnTheEditedPatchesOnly()
        {
            PatchGrid start = AuthoringGrids.Curved(PatchGrid.UniformLines(12), PatchGrid.UniformLines(10));
            var g = new EditedGrid(start);
            PatchGrid reader = start.Clone();   // the renderer's grid at version 1
            PatchEdit a = g.Dab(0.3, 0.4, 0.1, 0.02);
            int afterA = g.Version;
            PatchEdit b = g.Dab(0.7, 0.6, 0.12, -0.01);
            int[] expected = a.Patches.Union(b.Patches).OrderBy(p => p).ToArray();
            Assert.That(g.Log.ChangedSince(1), Is.EqualTo(expected));
            Assert.That(g.Log.ChangedSince(afterA), Is.EqualTo(b.Patches));
            Assert.That(g.Log.ChangedSince(g.Version), Is.Empty);
            Assert.That(g.Log.ChangedSince(999), Is.Null, "a version the log did not produce: rebuild");

            PatchGrid caught = g.Log.Update(reader, 1, g.Blocks, out int[] changed);
            Assert.That(changed, Is.EqualTo(expected));
            Assert.That(AuthoringGrids.SameBits(caught, g.Core), "the caught-up grid is the grid now, bit for bit");
            Assert.That(AuthoringGrids.SameBits(reader, start), "the reader's grid is not written (another thread may read it)");
            for (int p = 0; p < caught.PatchCount; p++)
                Assert.That(ReferenceEquals(caught.Patches[p], reader.Patches[p]), Is.EqualTo(Array.IndexOf(expected, p) < 0),
                    $"patch {p}: unchanged patches are shared, not converted again");
            // What the renderer uploads for them is what a whole upload holds there.
            GregoryPatchRecord[] whole = GpuLayout.PackPatchRecords(g.Core);
            foreach (int p in changed)
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                    Assert.That(GpuLayout.PackPatchRecord(caught.Patches[p])[k], Is.EqualTo(whole[p][k]));

            g.Log.Restart(++g.Version, g.Core.PatchCount);   // a whole-grid change (undo, replacement)
            Assert.That(g.Log.Update(caught, afterA, g.Blocks, out changed), Is.Null);
            Assert.That(changed, Is.Null);
        }

        [Test]
        public void AnEditThatBreaksASharedEdgeIsNotCaughtUpOn()
        {
            PatchGrid start = AuthoringGrids.Curved(PatchGrid.UniformLines(6), PatchGrid.UniformLines(6));
            var g = new EditedGrid(start);
            // Patch (2, 3)'s u = 0 column moved alone: its left neighbour (1, 3) still has the old points.
            int p = 3 * 6 + 2;
            Double3 q = PatchGridBlocks.Get(g.Blocks, p, GregoryPatch.Slot(0, 1));
            var moved = PatchGridBlocks.ReadPatch(g.Blocks, p);
            moved[GregoryPatch.Slot(0, 1)] = new Double3(q.x, q.y, q.z + 1e-3);
            PatchGridBlocks.SetPatch(g.Blocks, p, moved);
            g.Log.Add(++g.Version, new[] { p });
            Assert.That(g.Log.Update(start, 1, g.Blocks, out int[] changed), Is.Null, "the edge check of the changed patch fails: rebuild and report");
            var ex = Assert.Throws<ArgumentException>(() => new PatchGrid(6, 6, start.XLines, start.YLines, PatchGridBlocks.ToPatches(g.Blocks, 36)).ValidatePatches(new[] { p }));
            Assert.That(ex.Message, Does.Contain("patch (1, 3) and patch (2, 3)"));
            Assert.Throws<ArgumentOutOfRangeException>(() => start.ValidatePatches(new[] { 36 }));
        }

        [Test]
        public void TheQueryAfterAnEditAnswersAsANewQuery()
        {
            PatchGrid start = AuthoringGrids.Curved(PatchGrid.UniformLines(8), PatchGrid.UniformLines(8));
            var noise = new NoiseSettings(0.002f, 16f, 2f, 2f, 6);
            var before = new TerrainSurfaceQuery(start, noise);
            var g = new EditedGrid(start);
            g.Dab(0.5, 0.5, 0.2, 0.05);
            PatchGrid now = g.Log.Update(start, 1, g.Blocks, out int[] changed);
            TerrainSurfaceQuery edited = before.WithPatches(now, changed), fresh = new TerrainSurfaceQuery(now, noise);
            Assert.That(edited.MaxControlHeight, Is.GreaterThanOrEqualTo(fresh.MaxControlHeight));
            Assert.That(edited.MinControlHeight, Is.LessThanOrEqualTo(fresh.MinControlHeight));
            Assert.That(edited.SurfaceSlopeBound, Is.GreaterThanOrEqualTo(fresh.SurfaceSlopeBound));
            var rng = new Random(3);
            for (int k = 0; k < 200; k++)
            {
                double x = rng.NextDouble(), y = rng.NextDouble();
                Assert.That(edited.SampleHeight(x, y), Is.EqualTo(fresh.SampleHeight(x, y)), $"height at ({x}, {y})");
                var ray = new TerrainRay(new Double3(x, y, 1), new Double3(0.3, -0.2, -1), 3);
                Assert.That(edited.Raycast(ray, out TerrainRayHit h1, 1e-9), Is.EqualTo(fresh.Raycast(ray, out TerrainRayHit h2, 1e-9)));
                Assert.That(h1.distance, Is.EqualTo(h2.distance).Within(1e-8));
            }
            Assert.That(before.SampleHeight(0.5, 0.5), Is.LessThan(edited.SampleHeight(0.5, 0.5)), "the old query still answers for the old grid");
        }

        [Test]
        public void AWholeGridReplacementRecordsOnlyTheBlocksItChanges()
        {
            // 20 x 20 patches = 7 blocks of 64. Enforce G1 on a grid already G1 changes no bit; a dab,
            // then the same replacement, changes only the blocks under it.
            PatchGrid grid = AuthoringGrids.Curved(PatchGrid.UniformLines(20), PatchGrid.UniformLines(20));
            double[][] current = PatchGridBlocks.FromGrid(grid);
            PatchGrid g1 = grid.Clone();
            G1Builder.MakeG1(g1);
            Assert.That(PatchGridBlocks.ChangedBlocks(current, PatchGridBlocks.FromGrid(g1)), Is.Empty, "G1 on a G1 grid");
            PatchGrid edited = grid.Clone();
            PatchEdit dab = PatchBrush.Apply(edited, new BrushDab(BrushMode.Raise, 0.5, 0.05, 0.04, 0.01));
            dab.ApplyTo(edited);
            int[] expected = dab.Patches.Select(PatchGridBlocks.BlockOf).Distinct().OrderBy(b => b).ToArray();
            Assert.That(PatchGridBlocks.ChangedBlocks(current, PatchGridBlocks.FromGrid(edited)), Is.EqualTo(expected));
            Assert.That(expected.Length, Is.LessThan(current.Length));
            // A grid of another shape: every block of it is new or other.
            Assert.That(PatchGridBlocks.ChangedBlocks(current, PatchGridBlocks.FromGrid(PatchGrid.CreateFlat(21, 20))), Has.Length.EqualTo(7));
            // The fingerprint from per-block hashes, updated for the changed blocks, equals a whole rehash.
            ulong[] hashes = PatchGridBlocks.BlockHashes(current);
            double[][] after = PatchGridBlocks.FromGrid(edited);
            foreach (int b in expected) hashes[b] = PatchGridBlocks.BlockHash(after[b]);
            Assert.That(PatchGridBlocks.Combine(5, hashes), Is.EqualTo(PatchGridBlocks.Fingerprint(after, 5)));
            Assert.That(PatchGridBlocks.Fingerprint(after, 5), Is.Not.EqualTo(PatchGridBlocks.Fingerprint(current, 5)));
        }
        [Test]
        public void ATextureImportThatResamplesOrCompressesItsFileIsRefused()
        {
            Assert.That(TextureHeights.ImportProblem("h", 4097, 4097, 4097, 4097, "R16", compressed: false, readable: true), Is.Null);
            string capped = TextureHeights.ImportProblem("h", 4097, 4097, 2048, 2048, "R16", compressed: false, readable: true);
            Assert.That(capped, Does.Contain("'h'").And.Contain("imported at 2048 x 2048").And.Contain("file is 4097 x 4097"));
            string compressed = TextureHeights.ImportProblem("h", 513, 513, 513, 513, "DXT1", compressed: true, readable: true);
            Assert.That(compressed, Does.Contain("compressed (DXT1)").And.Contain("Compression to None"));
            string all = TextureHeights.ImportProblem("h", 1000, 600, 1024, 512, "BC6H", compressed: true, readable: false);
            Assert.That(all, Does.Contain("Read/Write is off").And.Contain("imported at 1024 x 512 but its file is 1000 x 600").And.Contain("BC6H"));
        }

        /// <summary>
        /// Review finding: an EXR of 32-bit floats imported as Unity's default RGBAHalf keeps 11 significant
        /// bits (0.3 m steps on a 600 m terrain) and nothing said so.
        /// </summary>
        [Test]
        public void AHalfImportOfA32BitExrIsRefused()
        {
            Assert.That(TextureHeights.ImportProblem("h", 513, 513, 513, 513, "RGBAHalf", compressed: false, readable: true, fileHas32BitChannels: false), Is.Null);
            Assert.That(TextureHeights.ImportProblem("h", 513, 513, 513, 513, "RFloat", compressed: false, readable: true, fileHas32BitChannels: true), Is.Null);
            string half = TextureHeights.ImportProblem("h", 513, 513, 513, 513, "RGBAHalf", compressed: false, readable: true, fileHas32BitChannels: true);
            Assert.That(half, Does.Contain("half precision (RGBAHalf: 11 significant bits)").And.Contain("32-bit floats"));
        }

        /// <summary>An OpenEXR header as the format lays it out: magic, version 2, attributes, the empty name.</summary>
        static byte[] ExrHeader(params int[] channelTypes)
        {
            var b = new List<byte>();
            void Int(int v) => b.AddRange(BitConverter.GetBytes(v));
            void Name(string n) { b.AddRange(System.Text.Encoding.ASCII.GetBytes(n)); b.Add(0); }
            Int(20000630); Int(2);
            Name("compression"); Name("compression"); Int(1); b.Add(0);
            var list = new List<byte>();
            for (int c = 0; c < channelTypes.Length; c++)
            {
                list.AddRange(System.Text.Encoding.ASCII.GetBytes("RGBA".Substring(c, 1))); list.Add(0);
                list.AddRange(BitConverter.GetBytes(channelTypes[c])); list.AddRange(new byte[4]);
                list.AddRange(BitConverter.GetBytes(1)); list.AddRange(BitConverter.GetBytes(1));
            }
            list.Add(0);
            Name("channels"); Name("chlist"); Int(list.Count); b.AddRange(list);
            Name("lineOrder"); Name("lineOrder"); Int(1); b.Add(0);
            b.Add(0);
            return b.ToArray();
        }

        [Test]
        public void ExrChannelTypesAreReadFromTheHeader()
        {
            Assert.That(TextureHeights.ExrHas32BitChannels(ExrHeader(1, 1, 1)), Is.False, "half channels");
            Assert.That(TextureHeights.ExrHas32BitChannels(ExrHeader(2)), Is.True, "one float channel");
            Assert.That(TextureHeights.ExrHas32BitChannels(ExrHeader(1, 0)), Is.True, "a uint channel");
            byte[] full = ExrHeader(2, 2);
            Assert.That(TextureHeights.ExrHas32BitChannels(full.Take(40).ToArray()), Is.Null, "a header cut inside its channel list");
            Assert.That(TextureHeights.ExrHas32BitChannels(new byte[] { 0x89, (byte)'P', (byte)'N', (byte)'G', 13, 10, 26, 10 }), Is.Null, "a PNG");
            Assert.That(TextureHeights.ExrHas32BitChannels(Array.Empty<byte>()), Is.Null);
            Assert.That(TextureHeights.ExrHas32BitChannels(null), Is.Null);
        }
    }
}
