using Unity.Profiling;
using UnityEngine;
using UnityEngine.Rendering;
#if UNITY_EDITOR
using UnityEditor.SceneManagement;
#endif

namespace GregoryTerrain
{
    // Drawing per camera: the callbacks each pipeline calls for every camera it renders (Game,
    // Scene view in Edit Mode, reflection probes, several cameras), which cameras draw, and the draw.
    public sealed partial class GregoryTerrainRenderer
    {
        /// <summary>Both registered, each pipeline calls its own: <c>beginCameraRendering</c> (URP, HDRP), <c>Camera.onPreCull</c> (Built-in).</summary>
        void RegisterCameraCallbacks()
        {
            RenderPipelineManager.beginCameraRendering += OnBeginCameraRendering;
            Camera.onPreCull += OnCameraPreCull;
        }

        void UnregisterCameraCallbacks()
        {
            RenderPipelineManager.beginCameraRendering -= OnBeginCameraRendering;
            Camera.onPreCull -= OnCameraPreCull;
        }

        void OnBeginCameraRendering(ScriptableRenderContext context, Camera cam) => DrawFor(cam);

        void OnCameraPreCull(Camera cam) => DrawFor(cam);

        /// <summary>
        /// One draw for one camera: <c>_Range</c> and, on change only, the rest (<see cref="Prepare"/>),
        /// then one Graphics.RenderPrimitives call that only <paramref name="cam"/> renders.
        /// </summary>
        internal void DrawFor(Camera cam)
        {
            if (cam == null || !DrawsIn(cam)) return;
            using (s_DrawMarker.Auto())
                Draw(cam);
        }

        // The Profiler's names for the per-camera work (a struct scope: nothing allocated).
        static readonly ProfilerMarker s_DrawMarker = new ProfilerMarker("GregoryTerrainRenderer.Draw");
        static readonly ProfilerMarker s_PrepareMarker = new ProfilerMarker("GregoryTerrainRenderer.Prepare");
        static readonly ProfilerMarker s_VertexCacheMarker = new ProfilerMarker("GregoryTerrainRenderer.VertexCache");

        void Draw(Camera cam)
        {
            bool prepared;
            using (s_PrepareMarker.Auto())
                prepared = Prepare(cam);
            if (!prepared) return;

            var rp = new RenderParams(_drawMaterial != null ? _drawMaterial : material)
            {
                camera = cam,
                worldBounds = WorldBounds(),
                matProps = _props,
                shadowCastingMode = shadowCasting,
                receiveShadows = receiveShadows,
                layer = gameObject.layer,
            };
            int across = TileLattice.TilesAcross(_params), tileCount = across * across;
            if (LevelsOn(_drawFallback)) tileCount = PushLevels();   // L x M^2 tiles, laid out around cam by Prepare(cam)
            if (_drawFallback)
                Graphics.RenderPrimitivesIndexed(rp, MeshTopology.Triangles, _fallbackIndices,
                    _fallbackIndices.count, 0, tileCount);
            else
                // One 4-control-point patch per tile; the vertex stage derives tile and corner from
                // SV_VertexID, so there is no vertex buffer.
                Graphics.RenderPrimitives(rp, MeshTopology.Quads, 4 * tileCount, 1);
        }

        /// <summary>Never a preview camera; in the editor only one whose scene culling mask shares a bit with ours (<see cref="CameraSceneFilter"/>; Prefab stages).</summary>
        bool DrawsIn(Camera cam)
        {
            if (cam.cameraType == CameraType.Preview) return false;
#if UNITY_EDITOR
            return CameraSceneFilter.Draws(gameObject.sceneCullingMask, SceneCullingMaskOf(cam));
#else
            return true;
#endif
        }

        /// <summary>
        /// <paramref name="cam"/>'s object -> clip and pixel size, from which every pass of its draw takes
        /// the factors; set only when they differ from what the property block holds.
        /// </summary>
        void PushTessellationView(Camera cam)
        {
            if (cam == null) return;
            int w = cam.pixelWidth, h = cam.pixelHeight;
            if (w <= 0 || h <= 0) return;   // renders nothing
            Matrix4x4 m = ObjectToClip(cam);
            var size = new Vector4(w, h, 1f / w, 1f / h);
            if (_props.HasMatrix(ShaderIds.TessObjectToClip) && VertexCachePass.SameMatrix(m, _props.GetMatrix(ShaderIds.TessObjectToClip))
                && VertexCachePass.SameVector(size, _props.GetVector(ShaderIds.TessScreenSize)))
                return;
            SetMatrix(ShaderIds.TessObjectToClip, m);
            SetVector(ShaderIds.TessScreenSize, size);
        }

#if UNITY_EDITOR
        static ulong SceneCullingMaskOf(Camera cam)
        {
            bool hasScene = cam.scene.IsValid();
            return CameraSceneFilter.CameraMask(cam.overrideSceneCullingMask, hasScene,
                hasScene ? EditorSceneManager.GetSceneCullingMask(cam.scene) : 0UL,
                cam.cameraType == CameraType.SceneView);
        }
#endif
    }
}
