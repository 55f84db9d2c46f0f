// --stencil (a ShaderLab Stencil block's body), --stencil-out and --stencil-in through the harness on
// lavapipe: the quad of the depth tests (a quarter of the target) drawn with a stencil state, the stencil
// read back in the PNG's row order and loaded again, as a frame's two passes chain it.
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    public partial class HarnessTests
    {
        /// <summary>Draws the depth tests' quad with the stencil block and the extra options; the run and the stencil after it.</summary>
        (HarnessRun Run, byte[] Stencil) DrawStencil(string name, string block, params string[] extra)
        {
            string dir = MakeDepthPlaneInputs("in_" + name);
            var (pos, idx) = WriteQuadMesh(name);
            string stencil = Path.Combine(_work, name + ".u8");
            HarnessRun r = HarnessRun.Harness(new[] { "--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"),
                "--frag", Spv("mesh.frag.spv"), "--buffers", dir, "--width", Size.ToString(), "--height", Size.ToString(),
                "--device", "llvmpipe", "--cull", "off", "--stencil", block, "--stencil-out", stencil }.Concat(extra).ToArray());
            r.AssertSucceeded();
            byte[] s = File.ReadAllBytes(stencil);
            Assert.That(s.Length, Is.EqualTo(Size * Size), "W * H bytes");
            return (r, s);
        }

        /// <summary>Pixel p (row-major, top row first) lies inside the quad (x, z in [0.25, 0.75]), away from its edges.</summary>
        static bool InQuad(int p) => Inside(p % Size) && Inside(p / Size);

        static bool Inside(int i) => i > Size / 4 + 1 && i < 3 * Size / 4 - 2;

        static bool OffQuad(int p) => Outside(p % Size) || Outside(p / Size);

        static bool Outside(int i) => i < Size / 4 - 2 || i > 3 * Size / 4 + 1;

        [Test]
        public void Stencil_WritesRefThroughWriteMask_WherePassReplaces_AndStencilInChainsTwoPasses()
        {
            // HDRP's pair: Ref 13 WriteMask 9 Replace writes 13 & 9 = 9 over the clear (0); then Ref 0 WriteMask 6 Replace
            // over a loaded 0xFF left half clears bits 1 and 2 only: 0xF9 where the quad drew, 0xFF beside it, 0 on the right.
            var (first, cleared) = DrawStencil("stencil_write", "Ref 13 WriteMask 9 Comp Always Pass Replace", "--depth-out",
                Path.Combine(_work, "stencil_write_depth.f32"));
            Assert.That(first.Stdout, Does.Contain(" stencil ref 13 read 255 write 9 front always replace keep keep back always replace keep keep"));
            Assert.That(Enumerable.Range(0, Size * Size).Where(InQuad).Select(p => cleared[p]).Distinct(), Is.EqualTo(new byte[] { 9 }), "inside the quad: 13 & 9");
            Assert.That(Enumerable.Range(0, Size * Size).Where(OffQuad).Select(p => cleared[p]).Distinct(), Is.EqualTo(new byte[] { 0 }), "outside: the clear");
            Assert.That(first.Value("stencil_out", Path.Combine(_work, "stencil_write.u8")), Is.EqualTo(new[] { Size.ToString(), Size.ToString(), "nonzero", (Size * Size / 4).ToString() }));
            Assert.That(first.Value("depth_out", Path.Combine(_work, "stencil_write_depth.f32"))[3], Is.EqualTo((Size * Size / 4).ToString()),
                "depth and stencil both read back from one attachment");

            string loaded = Path.Combine(_work, "stencil_in.u8");
            File.WriteAllBytes(loaded, Enumerable.Range(0, Size * Size).Select(p => (byte)(p % Size < Size / 2 ? 0xFF : 0)).ToArray());
            var (second, after) = DrawStencil("stencil_chain", "Ref 0 WriteMask 6 Comp Always Pass Replace", "--stencil-in", loaded);
            Assert.That(second.Value("stencil_in", loaded), Is.EqualTo(new[] { Size.ToString(), Size.ToString(), "nonzero", (Size * Size / 2).ToString() }));
            byte Expected(int p) => (byte)(p % Size >= Size / 2 ? 0 : InQuad(p) ? 0xF9 : 0xFF);
            int wrong = Enumerable.Range(0, Size * Size).Count(p => (InQuad(p) || OffQuad(p)) && after[p] != Expected(p));
            Assert.That(wrong, Is.Zero, "pixels whose stencil is not loaded & ~6 where the quad drew, the loaded value elsewhere");
        }

        [Test]
        public void Stencil_CompTestsRefAgainstTheLoadedValueThroughReadMask_AndFrontAndBackAreSeparate()
        {
            // Loaded 3 on the left half, 2 on the right; Ref 1 ReadMask 1 Comp Equal passes on the left only, IncrSat makes it 4.
            string loaded = Path.Combine(_work, "stencil_comp_in.u8");
            File.WriteAllBytes(loaded, Enumerable.Range(0, Size * Size).Select(p => (byte)(p % Size < Size / 2 ? 3 : 2)).ToArray());
            var (r, s) = DrawStencil("stencil_comp", "Ref 1 ReadMask 1 Comp Equal Pass IncrSat Fail Zero", "--stencil-in", loaded);
            Assert.That(r.Value("image", "nonsky_pixels")[0], Is.EqualTo((Size * Size / 8).ToString()), "the quad drew its left half only");
            byte Expected(int p) => (byte)(!InQuad(p) ? (p % Size < Size / 2 ? 3 : 2) : p % Size < Size / 2 ? 4 : 0);
            Assert.That(Enumerable.Range(0, Size * Size).Count(p => (InQuad(p) || OffQuad(p)) && s[p] != Expected(p)), Is.Zero,
                "IncrSat where the test passed, Zero (Fail) where it failed, the loaded value off the quad");

            // One face: CompFront/CompBack win over Comp, whatever their order; the quad has one facing (Cull Back tells which),
            // and only the Comp of that face decides whether it draws.
            var (culled, _) = DrawStencil("stencil_facing", "Comp Always", "--cull", "back");
            bool frontFacing = culled.Long("image", "nonsky_pixels") > 0;
            var (front, _) = DrawStencil("stencil_front", "CompFront Always CompBack Never");
            var (back, _) = DrawStencil("stencil_back", "CompFront Never Comp Never CompBack Always");
            long drawnFront = front.Long("image", "nonsky_pixels"), drawnBack = back.Long("image", "nonsky_pixels");
            TestContext.Out.WriteLine($"quad front-facing {frontFacing}; drawn under CompFront Always {drawnFront}, under CompBack Always {drawnBack}");
            Assert.That(drawnFront, Is.EqualTo(frontFacing ? Size * Size / 4 : 0), "drawn under CompFront Always, CompBack Never");
            Assert.That(drawnBack, Is.EqualTo(frontFacing ? 0 : Size * Size / 4), "drawn under CompFront Never, Comp Never, CompBack Always");
        }

        [TestCase("Ref 256", "Ref expects a whole number 0..255, got '256'")]
        [TestCase("Ref", "as pairs")]
        [TestCase("Comp LessEqual", "lequal")]
        [TestCase("Pass Incr", "incrsat")]
        [TestCase("ZFailFront Clear", "decrwrap")]
        [TestCase("Stencil 1", "'Stencil' is not a Stencil command")]
        [TestCase("Ref 1 ref 2", "ref is given twice")]
        public void StencilOption_BadBlock_Exit1NamingTheOptionAndValue(string block, string expected)
        {
            string dir = MakeInputs("in_4x4_f8", 4, 8, new[] { 0f, 0, 1, 1 });
            HarnessRun r = HarnessRun.Harness(TessArgs(dir, 4, 8, null).Concat(new[] { "--stencil", block }).ToArray());
            Assert.That(r.ExitCode, Is.EqualTo(1), r.Stdout + r.Stderr);
            Assert.That(r.Stderr, Does.Contain("--stencil").And.Contain(expected));
        }

        [Test]
        public void StencilFilesWithoutAStencilOrOfAnotherSizeOrOverManyFrames_AreRefused()
        {
            string dir = MakeInputs("in_stencil_bad", 4, 8, new[] { 0f, 0, 1, 1 });
            var (pos, idx) = WriteQuadMesh("stencil_bad");
            string small = Path.Combine(_work, "stencil_small.u8"), full = Path.Combine(_work, "stencil_full.u8");
            File.WriteAllBytes(small, new byte[Size]);
            File.WriteAllBytes(full, new byte[Size * Size]);
            foreach (var (extra, says) in new[] {
                (new[] { "--stencil-out", full }, "--stencil-out '" + full + "' needs the pass's stencil state: give --stencil"),
                (new[] { "--stencil-in", full }, "--stencil-in '" + full + "' needs the pass's stencil state"),
                (new[] { "--stencil", "Ref 1", "--stencil-in", small }, "--stencil-in '" + small + "' has " + Size + " bytes; expected"),
                (new[] { "--stencil", "Ref 1", "--stencil-in", full, "--frames", "2" }, "--stencil-in loads the stencil once: --frames must be 1") })
            {
                HarnessRun r = HarnessRun.Harness(new[] { "--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"), "--frag", Spv("mesh.frag.spv"),
                    "--buffers", dir, "--width", Size.ToString(), "--height", Size.ToString(), "--device", "llvmpipe" }.Concat(extra).ToArray());
                Assert.That(r.ExitCode, Is.EqualTo(1), r.Stdout + r.Stderr);
                Assert.That(r.Stderr, Does.Contain(says));
            }
        }
    }
}
