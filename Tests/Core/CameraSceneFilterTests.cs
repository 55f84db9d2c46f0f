using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The renderer's per-camera stage test (CameraSceneFilter): the cases Prefab Mode creates, with
    /// the masks Unity 2022.3 gives objects and cameras (a Prefab stage gets a bit of its own).
    /// </summary>
    public class CameraSceneFilterTests
    {
        const ulong Default = CameraSceneFilter.GameViewObjects | CameraSceneFilter.MainStageSceneViewObjects; // a main-scene object
        const ulong PrefabStage = 1UL << 5;   // a Prefab stage's allocated bit

        static bool Draws(ulong objectMask, ulong overrideMask, bool hasScene, ulong sceneMask, bool sceneView) =>
            CameraSceneFilter.Draws(objectMask, CameraSceneFilter.CameraMask(overrideMask, hasScene, sceneMask, sceneView));

        [Test]
        public void MainSceneObjectDrawsInGameAndMainStageSceneView()
        {
            Assert.That(Draws(Default, 0, false, 0, sceneView: false), Is.True, "Game camera");
            Assert.That(Draws(Default, CameraSceneFilter.MainStageSceneViewObjects, false, 0, sceneView: true), Is.True, "Scene view, main stage");
            Assert.That(Draws(Default, 0, false, 0, sceneView: true), Is.True, "Scene-view camera without an override");
        }

        [Test]
        public void PrefabStageIsolatesBothWays()
        {
            // Prefab Mode in isolation: the Scene view's override is 0 and its scene is the stage's.
            Assert.That(Draws(PrefabStage, 0, true, PrefabStage, sceneView: true), Is.True, "stage object in its stage");
            Assert.That(Draws(Default, 0, true, PrefabStage, sceneView: true), Is.False, "main-scene object in the stage");
            Assert.That(Draws(PrefabStage, 0, false, 0, sceneView: false), Is.False, "stage object in the Game view");
            Assert.That(Draws(PrefabStage, CameraSceneFilter.MainStageSceneViewObjects, false, 0, sceneView: true), Is.False,
                "stage object in a main-stage Scene view");
        }

        [Test]
        public void InContextModeShowsTheMainStageToo()
        {
            ulong inContext = PrefabStage | CameraSceneFilter.MainStageSceneViewObjects;
            Assert.That(Draws(PrefabStage, inContext, true, PrefabStage, sceneView: true), Is.True);
            Assert.That(Draws(Default, inContext, true, PrefabStage, sceneView: true), Is.True);
        }

        [Test]
        public void OverrideWinsOverSceneAndKind()
        {
            Assert.That(CameraSceneFilter.CameraMask(7UL, true, 9UL, true), Is.EqualTo(7UL));
            Assert.That(CameraSceneFilter.CameraMask(0UL, true, 9UL, true), Is.EqualTo(9UL));
            Assert.That(CameraSceneFilter.CameraMask(0UL, false, 9UL, false), Is.EqualTo(CameraSceneFilter.GameViewObjects));
        }
    }
}
