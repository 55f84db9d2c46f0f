using NUnit.Framework;
using UnityEngine;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The renderer's contract with the GPU, run in Unity (Edit Mode and Play Mode): the grid goes up
    /// once, a steady frame sets only <c>_Range</c> per camera, and disabling or a domain reload frees
    /// every native object it made. <c>DrawFor</c> is what each camera's rendering callback calls.
    /// </summary>
    [EditorOnly]   // draws with the package's shader, loaded through the AssetDatabase (TestTerrain)
    public class RendererLifecycleTests
    {
        TestTerrain _t;

        [SetUp] public void SetUp() => _t = new TestTerrain();
        [TearDown] public void TearDown() => _t.Dispose();

        [Test]
        public void UploadsOnceForEveryCameraAndFrame()
        {
            var r = _t.Renderer("terrain");
            Camera a = _t.Camera("a"), b = _t.Camera("b");
            for (int frame = 0; frame < 3; frame++) { r.DrawFor(a); r.DrawFor(b); }
            Assert.That(r.HasGpuResources, Is.True, "buffers held after drawing");
            Assert.That(r.UploadCount, Is.EqualTo(1), "uploads for 6 draws of one grid version");

            _t.Grid.MarkChanged();   // a new asset version uploads once more
            r.DrawFor(a); r.DrawFor(b);
            Assert.That(r.UploadCount, Is.EqualTo(2));
        }

        [Test]
        public void SteadyStateSetsOnlyRangePerCamera()
        {
            var r = _t.Renderer("terrain");
            Camera a = _t.Camera("a"), b = _t.Camera("b");
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare.Count, Is.GreaterThan(1), "the first draw sends the whole block");
            foreach (Camera cam in new[] { b, a, b })
            {
                r.DrawFor(cam);
                Assert.That(r.PropertiesSetLastPrepare, Is.EqualTo(new[] { ShaderIds.Range }),
                    $"properties set for camera {cam.name} in the steady state");
            }
            r.Range = new TerrainRange(0.25, 0.25, 0.5, 0.5);   // a pan and zoom: still _Range (+ lattice on a zoom), no upload
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Does.Contain(ShaderIds.Range));
            Assert.That(r.UploadCount, Is.EqualTo(1));
        }

        /// <summary>Each camera's draw carries its view (all its passes' factors), set only on change.</summary>
        [Test]
        public void EachCameraSendsItsTessellationViewOnlyWhenItDiffers()
        {
            var r = _t.Renderer("terrain");
            Camera a = _t.Camera("a"), b = _t.Camera("b");
            b.transform.position = new Vector3(0.5f, 2f, -3f);
            b.fieldOfView = 30f;
            Assert.That(a.pixelWidth, Is.GreaterThan(0), "cameras with pixels");
            int[] range = { ShaderIds.Range };
            int[] rangeAndView = { ShaderIds.Range, ShaderIds.TessObjectToClip, ShaderIds.TessScreenSize };
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Does.Contain(ShaderIds.TessObjectToClip).And.Contain(ShaderIds.TessScreenSize), "the first draw");
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Is.EqualTo(range), "a camera that holds still");
            r.DrawFor(b);
            Assert.That(r.PropertiesSetLastPrepare, Is.EqualTo(rangeAndView), "another camera");
            a.transform.position = new Vector3(0f, 1f, 0f);
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Is.EqualTo(rangeAndView), "the first, moved");
            r.ReleaseGpuResources();   // clears the property block
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Does.Contain(ShaderIds.TessObjectToClip), "a cleared block");
        }

        [Test]
        public void LevelCountIsSentAgainAfterTheBlockIsCleared()
        {
            var r = _t.Renderer("terrain");
            r.HorizonLevels = true;
            Camera a = _t.Camera("a");
            int levels = ShaderIds.LodLevels;
            Assume.That(r.DrawsFallback, Is.False, "the levels need the tessellator");
            r.DrawFor(a);
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Does.Not.Contain(levels), "steady");
            _t.Grid.MarkChanged();   // a re-upload (grid edit, undo) clears the block
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Does.Contain(levels), "after a re-upload");
            r.enabled = false;
            r.enabled = true;
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Does.Contain(levels), "after disable/enable");
        }

        [Test]
        public void DrawModeFollowsALoweredShaderLod()
        {
            var r = _t.Renderer("terrain");
            Camera a = _t.Camera("a");
            r.DrawFor(a);
            Assume.That(r.DrawsFallback, Is.False, "tessellated SubShader (LOD 300) in use");
            int lod = Shader.globalMaximumLOD;
            try
            {
                Shader.globalMaximumLOD = 250;   // between the fallback's 200 and the tessellated 300
                r.DrawFor(a);
                Assert.That(r.DrawsFallback, Is.True, "the fallback SubShader");
            }
            finally { Shader.globalMaximumLOD = lod; }
            r.DrawFor(a);
            Assert.That(r.DrawsFallback, Is.False, "and back");
        }

        [Test]
        public void DisableReleasesBuffersAndTheRuntimeMaterial()
        {
            var r = _t.Renderer("terrain");
            r.DrawFor(_t.Camera("a"));
            Material copy = r.UpdateDrawMaterial(FrameKeywords.VertexCache);
            Assert.That(copy, Is.Not.SameAs(_t.Asset), "a keyword the asset lacks is drawn from a copy");
            r.enabled = false;
            Assert.That(r.HasGpuResources, Is.False, "GPU buffers after OnDisable");
            Assert.That(r.DrawMaterial, Is.SameAs(_t.Asset), "the renderer holds no copy after OnDisable");
            // Play Mode destroys with Object.Destroy, which Unity carries out at the end of the frame.
            if (!Application.isPlaying) Assert.That(copy == null, Is.True, "the runtime material copy is destroyed on disable");
        }

        [Test]
        public void NoiseTableIsMadeAndSentOnlyWhileTheNoiseIsTiled()
        {
            var r = _t.Renderer("terrain");
            Camera a = _t.Camera("a");
            _t.Asset.EnableKeyword(ShaderKeywords.Noise);
            _t.Asset.DisableKeyword(ShaderKeywords.HeightColor);   // whatever the toggles' defaults did
            _t.Asset.DisableKeyword(ShaderKeywords.NoiseTable);
            r.DrawFor(a);
            Assert.That(r.HasNoiseTable, Is.False, "hashed noise (the default): no table");
            Assert.That(r.PropertiesSetLastPrepare, Does.Not.Contain(ShaderIds.NoiseCells));

            _t.Asset.EnableKeyword(ShaderKeywords.NoiseTable);   // the user switches Tiled noise on
            r.DrawFor(a);
            Assert.That(r.HasNoiseTable, Is.True, "tiled noise: the table is made");
            Assert.That(r.PropertiesSetLastPrepare, Does.Contain(ShaderIds.NoiseCells), "and sent");
            r.DrawFor(a);
            Assert.That(r.PropertiesSetLastPrepare, Is.EqualTo(new[] { ShaderIds.Range }), "sent once, not per frame");

            _t.Asset.DisableKeyword(ShaderKeywords.Noise);   // the table alone tiles nothing
            r.DrawFor(a);
            Assert.That(r.HasNoiseTable, Is.False, "GT_NOISE_TABLE without a noise: released");

            _t.Asset.EnableKeyword(ShaderKeywords.Noise);
            r.DrawFor(a);
            Assert.That(r.HasNoiseTable, Is.True);
            r.enabled = false;
            Assert.That(r.HasNoiseTable, Is.False, "released on disable");
        }

        [Test]
        public void DomainReloadHandlerReleasesEverything()
        {
            // ReleaseAll is what the renderer registers with AssemblyReloadEvents.beforeAssemblyReload
            // (whether or not OnDisable runs first); the rig checks that registration statically.
            var r = _t.Renderer("terrain");
            r.DrawFor(_t.Camera("a"));
            Material copy = r.UpdateDrawMaterial(FrameKeywords.Snow);
            r.ReleaseAll();
            Assert.That(r.HasGpuResources, Is.False);
            Assert.That(r.DrawMaterial, Is.SameAs(_t.Asset));
            if (!Application.isPlaying) Assert.That(copy == null, Is.True, "the runtime material copy is destroyed");
        }
    }
}
