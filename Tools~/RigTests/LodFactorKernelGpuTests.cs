// The Horizon levels' tile factors from the shipped compute kernels (Shaders/Cache/
// LevelFactorKernels.hlsl, LodFactorPieces and LodFactorSeams, as TerrainCache.compute compiles them
// with GT_LOD): on lavapipe, in one frame, the kernels' factors for every draw patch against the ones
// the hull stage computes for it without them (factor_readback+lod+noise, _LodLevels.y = 0), at
// 100 km and 1,000 km from the feet (the samples walking to the range origin). Equal bit for bit
// for every patch the hull draws: the same pieces and seam rule (LodSeamFactors; a fine seam edge
// takes g of the coarse edge's piece, which the kernel reads from the coarse tile's record instead
// of computing it again). The records are culled in no view (a shadow pass culls in the light's, not
// the camera's): tiles the camera's hull culls keep factors there. Then the hull reading the records
// (_LodLevels.y = 1, the renderer's path), culling in its own view, returns what it computes without.
using System.Collections.Generic;
using System.IO;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class LodFactorKernelGpuTests
    {
        const int Tiles = 8;
        string _work, _spirv, _kernels;
        PatchGrid _grid;

        [OneTimeSetUp]
        public void CompileShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-lod-factor-kernels");
            _spirv = ReadbackRun.CompileVariants(_work, "factor_readback+lod+noise");
            _kernels = Path.Combine(_work, "kernels");
            Directory.CreateDirectory(_kernels);
            string source = PackageRoot.Combine("Tools~", "rig", "TerrainRig.hlsl");
            foreach (string kernel in new[] { "LodFactorPieces", "LodFactorSeams" })
                ReadbackRun.Exec("glslangValidator", new[] { "-D", "-V", "-S", "comp", "-e", kernel, "--hlsl-iomap",
                    "--shift-cbuffer-binding", "0", "--shift-texture-binding", "2", "--shift-UAV-binding", "5",
                    "-DGT_LOD", "-DGT_NOISE", "-o", Path.Combine(_kernels, kernel + ".spv"), source }, null);
            _grid = HardCaseGrids.Fitted();
        }

        [TestCase(1e5)]
        [TestCase(1e6)]
        public void KernelFactorsEqualTheHullsBitForBit(double terrainMeters)
        {
            LodScene s = new LodScene { Tiles = Tiles, Factor = 0, Width = 1920, Height = 1080, TerrainMeters = terrainMeters }.Build(_grid);
            string dir = Path.Combine(_work, "t" + terrainMeters.ToString("0"));
            string hull = Path.Combine(dir, "hull.f32"), kernel = Path.Combine(dir, "kernel.f32"), read = Path.Combine(dir, "hull-read.f32");
            int p = s.Patches, r = LodFactorRecord.Stride / 4;   // floats a kernel record
            void Draw(LodScene scene, string readback, string dump)
            {
                scene.Write(dir);
                var args = new List<string>(ReadbackRun.Stages(_spirv, "factor_readback+lod+noise"));
                args.AddRange(scene.HarnessArgs(dir));
                args.AddRange(scene.KernelArgs(Path.Combine(_kernels, "LodFactorPieces.spv"), Path.Combine(_kernels, "LodFactorSeams.spv")));
                args.AddRange(new[] { "--width", "192", "--height", "108", "--device", "llvmpipe", "--readback", readback, "--readback-floats", (8 * p).ToString() });
                if (dump != null) args.AddRange(new[] { "--dump-storage", $"7:{dump}" });
                HarnessRun.Harness(args.ToArray()).AssertSucceeded();
            }
            Draw(s, hull, kernel);
            s.KernelFactors = true;
            Draw(s.Build(_grid), read, null);
            float[] h = ReadbackRun.ReadFloats(hull), k = ReadbackRun.ReadFloats(kernel), hr = ReadbackRun.ReadFloats(read);
            var f = s.Tail;
            Float4 Range(int level) => new Float4(f[4 + 4 * level], f[5 + 4 * level], f[6 + 4 * level], f[7 + 4 * level]);
            int fineSeamEdges = 0;   // drawn fine seam edges: their factor is g of the coarse tile's edge
            for (int level = 0; level + 1 < s.LevelCount; level++)
            {
                LodTiles.FinerOffsetCells(Range(level + 1), Range(level), Tiles, out int a, out int b);
                for (int slot = 0; slot < Tiles * Tiles; slot++)
                {
                    int mask = LodTiles.FineSeamEdges(slot % Tiles, slot / Tiles, a, b, Tiles);
                    for (int e = 0; e < 4; e++)
                        if ((mask & (1 << e)) != 0 && h[8 * (level * Tiles * Tiles + slot) + e] != 0f) fineSeamEdges++;
                }
            }
            int drawn = 0, differ = 0, readDiffers = 0, viewCulledKept = 0;
            string first = null;
            for (int i = 0; i < p; i++)
            {
                bool same = true, readSame = true;
                for (int c = 0; c < 6; c++)
                {
                    same &= h[8 * i] == 0f || h[8 * i + c] == k[r * i + c];
                    readSame &= hr[8 * i + c] == h[8 * i + c];
                }
                if (!readSame) readDiffers++;
                if (h[8 * i] != 0f) drawn++;
                else if (k[r * i] != 0f) viewCulledKept++;
                if (!same)
                {
                    differ++;
                    first ??= $"patch {i}: hull ({string.Join(", ", h[8 * i], h[8 * i + 1], h[8 * i + 2], h[8 * i + 3], h[8 * i + 4], h[8 * i + 5])})"
                              + $" kernel ({string.Join(", ", k[r * i], k[r * i + 1], k[r * i + 2], k[r * i + 3], k[r * i + 4], k[r * i + 5])})";
                }
            }
            TestContext.Out.WriteLine($"lod factor kernels, {terrainMeters / 1000:0} km: {p} patches, {drawn} drawn, {fineSeamEdges} fine seam edges drawn, {differ} differ from the hull{(first == null ? "" : "; first " + first)}; {viewCulledKept} culled by the camera's hull keep factors in the records; the hull reading the records: {readDiffers} differ");
            Assert.That(drawn, Is.GreaterThan(Tiles * Tiles), "the view draws tiles of several levels");
            Assert.That(fineSeamEdges, Is.GreaterThan(4), "the seam rule is exercised");
            Assert.That(differ, Is.EqualTo(0), first);
            Assert.That(viewCulledKept, Is.GreaterThan(0), "tiles off this camera's screen keep factors in the records: a shadow pass culls in its own view");
            Assert.That(readDiffers, Is.EqualTo(0), "the hull reading the kernels' records (_LodLevels.y = 1) and culling in its own view returns what it computes without them");
        }
    }
}
