using NUnit.Framework;
using UnityEngine;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// A PatchGridAsset under brush edits and undo (in Unity's Test Runner, Edit Mode): an edit keeps
    /// the grid valid and stamps a new version; a "something may have changed" mark (what any undo
    /// sends every loaded grid) keeps the version when the data is bit for bit the same, so renderers
    /// do not upload it again, and gives a new one when the data did change.
    /// </summary>
    public class PatchGridAssetEditTests
    {
        PatchGridAsset _asset;

        [SetUp]
        public void SetUp()
        {
            _asset = ScriptableObject.CreateInstance<PatchGridAsset>();
            _asset.SetGrid(PatchGrid.CreateFlat(10, 10));
        }

        [TearDown]
        public void TearDown()
        {
            foreach (PatchGridBlock b in _asset.Blocks) Object.DestroyImmediate(b);
            Object.DestroyImmediate(_asset);
        }

        [Test]
        public void AnUndoOfSomethingElseKeepsTheVersion()
        {
            int v0 = _asset.Version;
            _asset.MarkChangedOnNextRead();
            Assert.That(_asset.Version, Is.EqualTo(v0), "same data, same version: no upload");
            _asset.Blocks[0].Points[2] += 0.5;   // what an undo restoring a block does behind the asset's back
            _asset.MarkChangedOnNextRead();
            Assert.That(_asset.Version, Is.Not.EqualTo(v0), "changed data needs a new version");
        }

        [Test]
        public void ABrushEditKeepsTheGridValidAndStampsANewVersion()
        {
            int v0 = _asset.Version;
            PatchEdit edit = PatchBrush.Apply(_asset.ToPatchGrid(), new BrushDab(BrushMode.Raise, 0.5, 0.5, 0.2, 0.05));
            Assert.That(_asset.BlocksOf(edit), Is.Not.Empty);
            _asset.ApplyEdit(edit);
            Assert.That(_asset.Version, Is.Not.EqualTo(v0));
            Assert.That(_asset.IsValid, _asset.ValidationError);
            PatchGrid after = _asset.ToPatchGrid();
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(after), Is.LessThan(1e-7));
            Assert.That(after.Patch(5, 5)[GregoryPatch.Corner00].z, Is.GreaterThan(0.0));
        }

        [Test]
        public void AReaderCatchesUpOnADabAndRebuildsAfterAWholeChange()
        {
            PatchGrid before = _asset.ToPatchGrid();
            int v0 = _asset.Version;
            PatchEdit edit = PatchBrush.Apply(before.Clone(), new BrushDab(BrushMode.Raise, 0.5, 0.5, 0.2, 0.05));
            _asset.ApplyEdit(edit);
            PatchGrid caught = _asset.UpdatedPatchGrid(before, v0, out int[] changed);
            Assert.That(changed, Is.EqualTo(edit.Patches));
            PatchGrid now = _asset.ToPatchGrid();
            for (int p = 0; p < now.PatchCount; p++)
                for (int k = 0; k < GregoryPatch.SlotCount; k++) Assert.That(caught.Patches[p][k], Is.EqualTo(now.Patches[p][k]));
            _asset.SetGrid(PatchGrid.CreateFlat(10, 10));
            Assert.That(_asset.UpdatedPatchGrid(before, v0, out changed), Is.Null, "a whole-grid change: rebuild");
        }

        [Test]
        public void AReplacementWithTheSameBitsChangesNoBlock()
        {
            double[][] same = PatchGridBlocks.FromGrid(_asset.ToPatchGrid());
            Assert.That(_asset.BlocksChangedBy(same), Is.Empty, "nothing to record for Undo");
            same[1][5] += 1.0;
            Assert.That(_asset.BlocksChangedBy(same), Is.EqualTo(new[] { _asset.Blocks[1] }));
        }
    }
}
