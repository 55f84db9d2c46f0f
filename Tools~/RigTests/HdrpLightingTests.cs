using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// HDRP's forward pass lights the terrain in HDRP's physical units, as its Lit material beside it:
    /// the sun's illuminance (lux) through Lambert's 1/pi and the sky's ambient probe, both then
    /// pre-exposed. A constant ambient (0.2) times the exposure of a sunlit scene (about 2.5e-5 at
    /// EV 15) is 5e-6 of the display: every shadow and every slope facing away from the sun black.
    /// Checked on the real ForwardOnly fragment stage compiled against HDRP 14's libraries
    /// (Tools~/rig/shaderreads.py): what it reads and its constants. The picture itself needs an editor.
    /// </summary>
    [TestFixture]
    public class HdrpLightingTests
    {
        const string InvPi = "0.318309873";        // HDRP's Lambert(), INV_PI, as spirv-dis writes the float
        const string ConstantAmbient = "0.200000003";

        [TestCase("sub2 ForwardOnly")]
        [TestCase("sub3 ForwardOnly")]
        public void ForwardIsLitByTheSkysAmbientProbeAndTheSunThroughLambert(string pass)
        {
            var (reads, constants) = ReadsAndConstants("--pass", pass, "--stage", "frag", "--entry", "frag", "--define", "SHADOW_MEDIUM", "--constants");
            TestContext.Out.WriteLine($"{pass} frag reads: {string.Join(" ", reads)}\nconstants: {string.Join(" ", constants)}");
            Assert.That(reads, Does.Contain("_AmbientProbeData"), pass + ": the ambient from HDRP's sky probe (lux, as the sun: it survives the exposure)");
            Assert.That(reads, Does.Contain("_IndirectDiffuseLightingMultiplier"), pass + ": scaled by the Indirect Lighting Controller, as Lit's");
            Assert.That(reads, Does.Contain("_DirectionalLightDatas").And.Contain("_ExposureTexture"), pass + ": the sun, pre-exposed");
            Assert.That(constants, Does.Contain(InvPi), pass + ": the sun's illuminance through Lambert's 1/pi, as HDRP's Lit");
            Assert.That(constants, Does.Not.Contain(ConstantAmbient), pass + ": no constant ambient (not in HDRP's units)");
        }

        static (string[] reads, string[] constants) ReadsAndConstants(params string[] args)
        {
            var lines = TessellationViewTests.Run(args);
            string Line(string key) => lines.FirstOrDefault(l => l.StartsWith(key + ":"))?.Substring(key.Length + 1) ?? "";
            return (Line("reads").Split(' ', System.StringSplitOptions.RemoveEmptyEntries),
                    Line("constants").Split(' ', System.StringSplitOptions.RemoveEmptyEntries));
        }
    }
}
