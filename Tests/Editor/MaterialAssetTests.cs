using NUnit.Framework;
using UnityEditor.SceneManagement;
using UnityEngine;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Per-renderer shader state, in the editor: keywords a renderer's settings choose never reach the
    /// material asset, and two renderers sharing one material each draw with their own keywords.
    /// </summary>
    public class MaterialAssetTests
    {
        TestTerrain _t;

        [SetUp] public void SetUp() => _t = new TestTerrain();
        [TearDown] public void TearDown() => _t.Dispose();

        [Test]
        public void TwoRenderersWithDifferentSettingsLeaveTheAssetUntouched()
        {
            _t.Asset.EnableKeyword(ShaderKeywords.Noise);   // a keyword the user chose
            string[] keywordsBefore = _t.Asset.shaderKeywords;
            int crcBefore = _t.Asset.ComputeCRC();

            GregoryTerrainRenderer cached = _t.Renderer("cached"), snowy = _t.Renderer("snowy"), plain = _t.Renderer("plain");
            Camera cam = _t.Camera("cam");
            plain.DrawFor(cam); cached.DrawFor(cam); snowy.DrawFor(cam);
            Material a = cached.UpdateDrawMaterial(FrameKeywords.VertexCache);
            Material b = snowy.UpdateDrawMaterial(FrameKeywords.Snow);
            Material c = plain.UpdateDrawMaterial(FrameKeywords.None);

            Assert.That(_t.Asset.shaderKeywords, Is.EquivalentTo(keywordsBefore), "asset keywords");
            Assert.That(_t.Asset.ComputeCRC(), Is.EqualTo(crcBefore), "asset content (CRC)");
            Assert.That(_t.Asset.IsKeywordEnabled(ShaderKeywords.VertexCache), Is.False);
            Assert.That(_t.Asset.IsKeywordEnabled(ShaderKeywords.Snow), Is.False);

            Assert.That(a, Is.Not.SameAs(_t.Asset));
            Assert.That(a.IsKeywordEnabled(ShaderKeywords.VertexCache), Is.True, "cached: GT_VERTEX_CACHE");
            Assert.That(a.IsKeywordEnabled(ShaderKeywords.Snow), Is.False, "cached: no GT_SNOW");
            Assert.That(b.IsKeywordEnabled(ShaderKeywords.Snow), Is.True, "snowy: GT_SNOW");
            Assert.That(b.IsKeywordEnabled(ShaderKeywords.VertexCache), Is.False, "snowy: no GT_VERTEX_CACHE");
            Assert.That(c, Is.SameAs(_t.Asset), "a renderer that adds no keyword draws the asset itself");
            foreach (Material m in new[] { a, b })
            {
                Assert.That(m.IsKeywordEnabled(ShaderKeywords.Noise), Is.True, "the asset's own keywords are kept");
                Assert.That((m.hideFlags & HideFlags.DontSaveInEditor) != 0, Is.True, "the copy is never saved");
            }
        }

        [Test]
        public void CopyFollowsTheAssetWhenItChanges()
        {
            var r = _t.Renderer("cached");
            r.DrawFor(_t.Camera("cam"));
            Material copy = r.UpdateDrawMaterial(FrameKeywords.VertexCache);
            Assert.That(copy.IsKeywordEnabled(ShaderKeywords.HeightColor), Is.False);
            _t.Asset.EnableKeyword(ShaderKeywords.HeightColor);   // the user edits the asset
            Assert.That(r.UpdateDrawMaterial(FrameKeywords.VertexCache), Is.SameAs(copy), "the same copy, synced");
            Assert.That(copy.IsKeywordEnabled(ShaderKeywords.HeightColor), Is.True, "the asset's change reached the copy");
            Assert.That(copy.IsKeywordEnabled(ShaderKeywords.VertexCache), Is.True, "the renderer's keyword survives the sync");
            Assert.That(_t.Asset.IsKeywordEnabled(ShaderKeywords.VertexCache), Is.False);
        }

        /// <summary>Core's CameraSceneFilter restates Unity's scene culling bits: they must stay equal.</summary>
        [Test]
        public void SceneCullingBitsMatchUnity()
        {
            Assert.That(CameraSceneFilter.GameViewObjects, Is.EqualTo(SceneCullingMasks.GameViewObjects));
            Assert.That(CameraSceneFilter.MainStageSceneViewObjects, Is.EqualTo(SceneCullingMasks.MainStageSceneViewObjects));
        }

        [Test]
        public void MainSceneCameraDrawsAMainSceneTerrain()
        {
            var r = _t.Renderer("terrain");
            Camera cam = _t.Camera("cam");
            Assert.That(CameraSceneFilter.Draws(r.gameObject.sceneCullingMask,
                CameraSceneFilter.CameraMask(cam.overrideSceneCullingMask, cam.scene.IsValid(), 0UL, false)), Is.True);
            r.DrawFor(cam);
            Assert.That(r.UploadCount, Is.EqualTo(1), "the game camera drew it (and uploaded once)");
        }
    }
}
