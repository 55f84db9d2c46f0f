using NUnit.Framework;
using UnityEngine;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Range controllers in Edit Mode (where the editor's Test Runner runs these): they preview the
    /// range without writing saved state, and the zoom controller never moves a camera the user is
    /// placing unless Place Camera In Edit Mode is on.
    /// </summary>
    public class RangeControllerEditModeTests
    {
        TestTerrain _t;

        [SetUp] public void SetUp() => _t = new TestTerrain();
        [TearDown] public void TearDown() => _t.Dispose();

        [Test]
        public void ZoomControllerPreviewsWithoutSavingOrMovingTheCamera()
        {
            Assume.That(Application.isPlaying, Is.False, "an Edit Mode test");
            GregoryTerrainRenderer r = _t.Renderer("terrain");
            Camera cam = _t.Camera("view");
            var placed = new Vector3(3f, 4f, 5f);
            cam.transform.position = placed;
            Vector4 saved = r.SavedRange;

            var zoom = cam.gameObject.AddComponent<ZoomRangeController>();
            zoom.Target = r;
            zoom.ViewCamera = cam;
            zoom.Zoom(2f, new Vector2(0.5f, 0.5f));   // width 1/4
            zoom.Apply();

            Assert.That(r.Range.Width, Is.EqualTo(0.25).Within(1e-12), "the drawn range follows the controller");
            Assert.That(r.SavedRange, Is.EqualTo(saved), "the renderer's saved range is not written in Edit Mode");
            Assert.That(cam.transform.position, Is.EqualTo(placed), "the camera stays where the user put it");

            zoom.PlaceCameraInEditMode = true;   // asked for: now it moves
            zoom.Apply();
            Assert.That(cam.transform.position, Is.Not.EqualTo(placed));
        }
    }
}
