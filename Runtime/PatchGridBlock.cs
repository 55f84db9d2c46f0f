using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// One block of a <see cref="PatchGridAsset"/>'s control points (Core's PatchGridBlocks layout:
    /// up to 64 patches, 60 doubles each), saved as a hidden sub-asset of the grid. The grid is cut into
    /// blocks so that an edit records for Undo only the blocks it changes, not the whole grid.
    /// </summary>
    internal sealed class PatchGridBlock : ScriptableObject
    {
        [Tooltip("The grid this block belongs to.")]
        [SerializeField] PatchGridAsset owner;

        [Tooltip("Control points (x, y, z) of this block's patches, 20 per patch in GregoryPatch slot order.")]
        [SerializeField] double[] points;

        /// <summary>The grid this block belongs to.</summary>
        public PatchGridAsset Owner => owner;

        /// <summary>The block's doubles; the owning grid reads and writes them in place.</summary>
        internal double[] Points { get => points; set => points = value; }

        internal static PatchGridBlock Create(PatchGridAsset owner, int index, double[] points)
        {
            var block = CreateInstance<PatchGridBlock>();
            block.name = $"Block {index}";
            block.hideFlags = HideFlags.HideInHierarchy;   // a grid of 256 x 256 patches has 1024 of them
            block.owner = owner;
            block.points = points;
            return block;
        }

        // Undo and redo restore a block's doubles: the grid must re-validate and stamp a new version
        // so renderers upload it again. Unity calls this for every block as the grid loads too, so the
        // grid checks itself once, on its next read, not once per block.
        void OnValidate()
        {
            if (owner != null) owner.MarkChangedOnNextRead();
        }
    }
}
