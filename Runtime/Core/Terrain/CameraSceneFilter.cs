namespace GregoryTerrain
{
    /// <summary>
    /// Which cameras draw an object, as the editor decides it for its own renderers: by scene culling
    /// masks (64-bit, one bit per stage). An object is drawn by a camera when their masks share a bit.
    /// A draw submitted by script (Graphics.RenderPrimitives) gets no such test from Unity, so the
    /// renderer makes it before drawing for a camera; this is how an instance in a Prefab stage draws
    /// only in that stage's Scene view and a main-scene instance stays out of it.
    /// The bits and the camera's choice of mask follow Unity 2022.3 (UnityEditor.SceneManagement.SceneCullingMasks,
    /// Camera.overrideSceneCullingMask, Camera.scene); a player has no stages and draws in every camera.
    /// </summary>
    internal static class CameraSceneFilter
    {
        /// <summary>Objects the Game view draws (SceneCullingMasks.GameViewObjects).</summary>
        public const ulong GameViewObjects = 1UL << 63;

        /// <summary>Objects of the main stage that the Scene view draws (SceneCullingMasks.MainStageSceneViewObjects).</summary>
        public const ulong MainStageSceneViewObjects = (1UL << 62) | (1UL << 61);

        /// <summary>
        /// The mask a camera draws with: its override when set (the Scene view sets one per stage),
        /// else that of the scene it is bound to (preview and Prefab-stage cameras), else by kind:
        /// a Scene-view camera the main stage's Scene-view objects, any other camera the Game view's.
        /// </summary>
        /// <param name="overrideMask">Camera.overrideSceneCullingMask (0 = none).</param>
        /// <param name="hasScene">Camera.scene.IsValid().</param>
        /// <param name="sceneMask">EditorSceneManager.GetSceneCullingMask(Camera.scene); read only when <paramref name="hasScene"/>.</param>
        /// <param name="isSceneView">Camera.cameraType == CameraType.SceneView.</param>
        public static ulong CameraMask(ulong overrideMask, bool hasScene, ulong sceneMask, bool isSceneView)
        {
            if (overrideMask != 0) return overrideMask;
            if (hasScene) return sceneMask;
            return isSceneView ? MainStageSceneViewObjects : GameViewObjects;
        }

        /// <summary>True when a camera with <paramref name="cameraMask"/> draws an object with <paramref name="objectMask"/> (GameObject.sceneCullingMask).</summary>
        public static bool Draws(ulong objectMask, ulong cameraMask) => (objectMask & cameraMask) != 0;
    }
}
