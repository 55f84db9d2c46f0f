using NUnit.Framework;
using System.Linq;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The renderer's old flat settings (a scene saved before the settings were Core structs) move into
    /// the structs after a load; data saved since holds the old fields unset and is left alone.
    /// </summary>
    [TestFixture]
    public class FlatSettingsUpgradeTests
    {
        const int UnsetI = FlatSettingsUpgrade.UnsetInt;
        const float UnsetF = FlatSettingsUpgrade.UnsetFloat;

        /// <summary>The renderer's fields as Unity leaves them after a load: the structs and the hidden old ones.</summary>
        sealed class Loaded
        {
            public TessellationSettings tessellation = TessellationSettings.Default;
            public NoiseSettings noise = new NoiseSettings(0.02f, 16f, 2f, 2f, 6);
            public HeightColorSettings heightColor = new HeightColorSettings(0.5f, 0.1f, 64f);
            public int tiles = UnsetI, uniformFactor = UnsetI, noiseOctaves = UnsetI;
            public float maxFactor = UnsetF, targetPixelError = UnsetF, noiseAmplitude = UnsetF, noiseFrequency = UnsetF,
                noiseAlpha = UnsetF, noiseBeta = UnsetF, colorGamma = UnsetF, colorNoiseAmplitude = UnsetF, colorNoiseFrequency = UnsetF;

            public bool Upgrade() => FlatSettingsUpgrade.Move(ref tessellation, ref noise, ref heightColor,
                tiles: ref tiles, maxFactor: ref maxFactor, targetPixelError: ref targetPixelError, uniformFactor: ref uniformFactor,
                noiseAmplitude: ref noiseAmplitude, noiseFrequency: ref noiseFrequency, noiseAlpha: ref noiseAlpha, noiseBeta: ref noiseBeta,
                noiseOctaves: ref noiseOctaves, colorGamma: ref colorGamma, colorNoiseAmplitude: ref colorNoiseAmplitude,
                colorNoiseFrequency: ref colorNoiseFrequency);

            public bool AllOldUnset => tiles == UnsetI && uniformFactor == UnsetI && noiseOctaves == UnsetI
                && new[] { maxFactor, targetPixelError, noiseAmplitude, noiseFrequency, noiseAlpha, noiseBeta, colorGamma, colorNoiseAmplitude, colorNoiseFrequency }
                    .All(v => v == UnsetF);
        }

        [Test]
        public void AnOldScenesFlatValuesMoveIntoTheStructs()
        {
            // Every value differs from the defaults and from each other: a field moved to the wrong place shows.
            var r = new Loaded
            {
                tiles = 24, maxFactor = 48f, targetPixelError = 3.5f, uniformFactor = 5,
                noiseAmplitude = 0.031f, noiseFrequency = 27f, noiseAlpha = 2.25f, noiseBeta = 1.75f, noiseOctaves = 9,
                colorGamma = 0.73f, colorNoiseAmplitude = 0.17f, colorNoiseFrequency = 91f,
            };
            bool moved = r.Upgrade();
            Assert.That(r.noise, Is.EqualTo(new NoiseSettings(0.031f, 27f, 2.25f, 1.75f, 9)));
            Assert.That(r.tessellation, Is.EqualTo(new TessellationSettings(24, 48f, 3.5f, 5f)));
            Assert.That(r.heightColor, Is.EqualTo(new HeightColorSettings(0.73f, 0.17f, 91f)));
            Assert.That(moved, Is.True);
            Assert.That(r.AllOldUnset, "each old field is unset once moved, so the next load does not move it again");
        }

        [Test]
        public void DataSavedInTheNewLayoutIsLeftAlone()
        {
            var r = new Loaded
            {
                tessellation = new TessellationSettings(32, 40f, 2f, 0f),
                noise = new NoiseSettings(0.05f, 12f, 3f, 2.5f, 8),
                heightColor = new HeightColorSettings(1.5f, 0f, 8f),
            };
            Assert.That(r.Upgrade(), Is.False);
            Assert.That(r.tessellation, Is.EqualTo(new TessellationSettings(32, 40f, 2f, 0f)));
            Assert.That(r.noise, Is.EqualTo(new NoiseSettings(0.05f, 12f, 3f, 2.5f, 8)));
            Assert.That(r.heightColor, Is.EqualTo(new HeightColorSettings(1.5f, 0f, 8f)));
            Assert.That(r.AllOldUnset);
        }

        [Test]
        public void AnOldPrefabOverrideOfOneFieldMovesThatFieldOnly()
        {
            // A prefab saved in the new layout, its scene instance saved before with "tiles: 32" and
            // "noiseOctaves: 0" as overrides: Unity applies them to the old fields, then the load moves them.
            var r = new Loaded { tessellation = new TessellationSettings(16, 64f, 8f, 0f), tiles = 32, noiseOctaves = 0 };
            Assert.That(r.Upgrade(), Is.True);
            Assert.That(r.tessellation, Is.EqualTo(new TessellationSettings(32, 64f, 8f, 0f)));
            Assert.That(r.noise, Is.EqualTo(new NoiseSettings(0.02f, 16f, 2f, 2f, 0)));
            Assert.That(r.heightColor, Is.EqualTo(new HeightColorSettings(0.5f, 0.1f, 64f)));
            Assert.That(r.AllOldUnset);
            r.tessellation.tiles = 8;   // edited after the load
            Assert.That(r.Upgrade(), Is.False, "a second load without the old data moves nothing");
            Assert.That(r.tessellation.tiles, Is.EqualTo(8));
        }

        [Test]
        public void OldZerosAreValuesNotUnset()
        {
            var r = new Loaded { uniformFactor = 0, noiseAmplitude = 0f, colorNoiseAmplitude = 0f, noiseOctaves = 0 };
            r.tessellation.uniformFactor = 4f; r.noise.amplitude = 0.3f;
            Assert.That(r.Upgrade(), Is.True);
            Assert.That(r.tessellation.uniformFactor, Is.EqualTo(0f));
            Assert.That(r.noise.amplitude, Is.EqualTo(0f));
            Assert.That(r.noise.octaves, Is.EqualTo(0));
            Assert.That(r.heightColor.noiseAmplitude, Is.EqualTo(0f));
        }
    }
}
