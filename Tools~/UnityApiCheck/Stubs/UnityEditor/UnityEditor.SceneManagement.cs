// STUB members for Prefab Mode isolation of per-camera draws (issue 23, runtime half), in a file of
// their own so the editor half's stub edits merge cleanly. Written from the 2022.3 Scripting
// Reference (SR:<Page>) and checked against Unity's C# reference source for 2022.3.
#pragma warning disable CS0067, CS1591
using UnityEngine.SceneManagement;

namespace UnityEditor.SceneManagement
{
    public sealed partial class EditorSceneManager : SceneManager                                    // SR:SceneManagement.EditorSceneManager
    {
        public static ulong GetSceneCullingMask(Scene scene) => 0;                          // SR:SceneManagement.EditorSceneManager.GetSceneCullingMask
        public static bool IsPreviewScene(Scene scene) => false;                            // SR:SceneManagement.EditorSceneManager.IsPreviewScene
    }

    public static class SceneCullingMasks                                                    // SR:SceneManagement.SceneCullingMasks
    {
        public const ulong DefaultSceneCullingMask = GameViewObjects | MainStageSceneViewObjects; // SR:SceneManagement.SceneCullingMasks.DefaultSceneCullingMask
        public const ulong GameViewObjects = 1UL << 63;                                     // SR:SceneManagement.SceneCullingMasks.GameViewObjects
        public const ulong MainStageSceneViewObjects = (1UL << 61) | (1UL << 62);           // SR:SceneManagement.SceneCullingMasks.MainStageSceneViewObjects
    }
}
