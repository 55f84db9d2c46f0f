using System;
using System.Collections.Generic;

namespace GregoryTerrain
{
    /// <summary>
    /// A patch grid's control points cut into blocks of <see cref="PatchesPerBlock"/> patches, so that
    /// an edit touches (and an undo step records) only the blocks it changes, not the whole grid.
    /// Patch <c>p</c> lives in block <c>p / PatchesPerBlock</c> at doubles
    /// <c>(p % PatchesPerBlock) * DoublesPerPatch</c>: 20 control points (x, y, z) in GregoryPatch slot
    /// order, as in the flat layout (internals.md). The last block holds the remaining patches only.
    /// </summary>
    internal static class PatchGridBlocks
    {
        /// <summary>Patches per block: 64 x 60 doubles = 30,720 bytes of control points.</summary>
        public const int PatchesPerBlock = 64;

        /// <summary>Doubles per patch: 20 points of (x, y, z).</summary>
        public const int DoublesPerPatch = 3 * GregoryPatch.SlotCount;

        /// <summary>Bytes of control points in a full block.</summary>
        public const int BlockBytes = PatchesPerBlock * DoublesPerPatch * sizeof(double);

        /// <summary>Blocks needed for <paramref name="patchCount"/> patches.</summary>
        public static int BlockCount(int patchCount)
        {
            if (patchCount < 1) throw new ArgumentOutOfRangeException(nameof(patchCount), patchCount, "patchCount must be at least 1");
            return (patchCount + PatchesPerBlock - 1) / PatchesPerBlock;
        }

        /// <summary>Doubles in block <paramref name="block"/> of a grid of <paramref name="patchCount"/> patches.</summary>
        public static int BlockLength(int block, int patchCount) =>
            Math.Min(PatchesPerBlock, patchCount - block * PatchesPerBlock) * DoublesPerPatch;

        /// <summary>Cuts a flat control point array (the old single-array layout) into blocks; copies, never shares.</summary>
        public static double[][] Split(double[] controlPoints, int patchCount)
        {
            if (controlPoints == null) throw new ArgumentNullException(nameof(controlPoints));
            if (controlPoints.Length != patchCount * DoublesPerPatch)
                throw new ArgumentException($"controlPoints.Length = {controlPoints.Length}, expected {patchCount * DoublesPerPatch} (= 60 x {patchCount} patches)", nameof(controlPoints));
            var blocks = new double[BlockCount(patchCount)][];
            for (int b = 0; b < blocks.Length; b++)
            {
                blocks[b] = new double[BlockLength(b, patchCount)];
                Array.Copy(controlPoints, b * PatchesPerBlock * DoublesPerPatch, blocks[b], 0, blocks[b].Length);
            }
            return blocks;
        }

        /// <summary>Why <paramref name="blocks"/> cannot hold <paramref name="patchCount"/> patches (names the block and length), or null.</summary>
        public static string CheckShape(double[][] blocks, int patchCount)
        {
            int expected = BlockCount(patchCount);
            if (blocks == null || blocks.Length != expected) return $"blocks.Length = {blocks?.Length ?? 0}, expected {expected} for {patchCount} patches";
            for (int b = 0; b < blocks.Length; b++)
            {
                int want = BlockLength(b, patchCount);
                if (blocks[b] == null || blocks[b].Length != want) return $"blocks[{b}].Length = {blocks[b]?.Length ?? 0}, expected {want}";
            }
            return null;
        }

        /// <summary>Control point <paramref name="slot"/> of <paramref name="patch"/>.</summary>
        public static Double3 Get(double[][] blocks, int patch, int slot) => Get(blocks[BlockOf(patch)], patch, slot);

        /// <summary>The block holding <paramref name="patch"/>.</summary>
        public static int BlockOf(int patch) => patch / PatchesPerBlock;

        /// <summary>
        /// Control point <paramref name="slot"/> of <paramref name="patch"/>, read from the one block that
        /// holds it (<c>blocks[BlockOf(patch)]</c>): for callers that would otherwise build the block
        /// list for every point (the Scene view reads every point of the grid each repaint).
        /// </summary>
        public static Double3 Get(double[] block, int patch, int slot)
        {
            int k = Offset(patch, slot);
            return new Double3(block[k], block[k + 1], block[k + 2]);
        }

        /// <summary>The patches of a grid as Core patches (for <see cref="PatchGrid"/>).</summary>
        public static GregoryPatch[] ToPatches(double[][] blocks, int patchCount)
        {
            var patches = new GregoryPatch[patchCount];
            for (int p = 0; p < patchCount; p++) patches[p] = ReadPatch(blocks, p);
            return patches;
        }

        /// <summary>Patch <paramref name="patch"/> as a new Core patch.</summary>
        public static GregoryPatch ReadPatch(double[][] blocks, int patch)
        {
            var result = new GregoryPatch();
            for (int s = 0; s < GregoryPatch.SlotCount; s++) result[s] = Get(blocks, patch, s);
            return result;
        }

        /// <summary>The blocks of <paramref name="grid"/>'s patches.</summary>
        public static double[][] FromGrid(PatchGrid grid)
        {
            var blocks = new double[BlockCount(grid.PatchCount)][];
            for (int b = 0; b < blocks.Length; b++) blocks[b] = new double[BlockLength(b, grid.PatchCount)];
            for (int p = 0; p < grid.PatchCount; p++)
                for (int s = 0; s < GregoryPatch.SlotCount; s++)
                    Write(blocks, p, s, grid.Patches[p][s]);
            return blocks;
        }

        /// <summary>
        /// The blocks that <see cref="MoveControlPoint"/> may change for this point, ascending: the
        /// patch's own block and, for a boundary slot (stored once in every patch sharing it), the blocks
        /// of the 3 x 3 patches around it. Record these, and only these, before the move.
        /// </summary>
        public static int[] BlocksTouchedByMove(int columns, int rows, int patch, int slot)
        {
            CheckPoint(columns, rows, patch, slot);
            var touched = new SortedSet<int> { patch / PatchesPerBlock };
            if (IsBoundarySlot(slot))
            {
                int pi = patch % columns, pj = patch / columns;
                for (int j = Math.Max(pj - 1, 0); j <= Math.Min(pj + 1, rows - 1); j++)
                for (int i = Math.Max(pi - 1, 0); i <= Math.Min(pi + 1, columns - 1); i++)
                    touched.Add((j * columns + i) / PatchesPerBlock);
            }
            var result = new int[touched.Count];
            touched.CopyTo(result);
            return result;
        }

        /// <summary>
        /// Moves one control point. A boundary point is stored once per patch sharing it, bit for bit
        /// (PatchGrid.Validate and the GPU's watertight edges rely on it), so every copy in the
        /// neighbouring patches moves with it. Returns the blocks it changed (a subset of
        /// <see cref="BlocksTouchedByMove"/>). Throws, changing nothing, on a non-finite position.
        /// </summary>
        public static int[] MoveControlPoint(double[][] blocks, int columns, int rows, int patch, int slot, Double3 position)
        {
            CheckPoint(columns, rows, patch, slot);
            if (!double.IsFinite(position.x) || !double.IsFinite(position.y) || !double.IsFinite(position.z))
                throw new ArgumentException($"control point ({patch}, {slot}) = ({position.x}, {position.y}, {position.z}) must be finite", nameof(position));
            Double3 old = Get(blocks, patch, slot);
            var changed = new SortedSet<int>();
            if (IsBoundarySlot(slot))
            {
                // The copies of a shared boundary point sit in the 3 x 3 block of patches around it.
                int pi = patch % columns, pj = patch / columns;
                for (int j = Math.Max(pj - 1, 0); j <= Math.Min(pj + 1, rows - 1); j++)
                for (int i = Math.Max(pi - 1, 0); i <= Math.Min(pi + 1, columns - 1); i++)
                for (int s = 0; s < 16; s++)
                {
                    int q = j * columns + i;
                    if (!IsBoundarySlot(s) || (q == patch && s == slot)) continue;
                    if (SameBits(Get(blocks, q, s), old)) { Write(blocks, q, s, position); changed.Add(q / PatchesPerBlock); }
                }
            }
            Write(blocks, patch, slot, position);
            changed.Add(patch / PatchesPerBlock);
            var result = new int[changed.Count];
            changed.CopyTo(result);
            return result;
        }

        /// <summary>Writes all 20 control points of <paramref name="patch"/> (an edit's new patch: PatchEdit).</summary>
        public static void SetPatch(double[][] blocks, int patch, GregoryPatch value)
        {
            if (value == null) throw new ArgumentNullException(nameof(value));
            for (int s = 0; s < GregoryPatch.SlotCount; s++) Write(blocks, patch, s, value[s]);
        }

        /// <summary>
        /// A 64-bit fingerprint of the blocks' doubles (their bits, in order): equal data, equal
        /// fingerprint. Lets a grid tell after an undo whether its data really changed (a different
        /// fingerprint) without validating it whole, so unrelated undos do not re-upload it.
        /// </summary>
        public static ulong Fingerprint(double[][] blocks, ulong seed) => Combine(seed, BlockHashes(blocks));

        /// <summary>
        /// <see cref="Fingerprint"/> from each block's <see cref="BlockHash"/>: after an edit only the
        /// blocks it wrote are hashed again (a brush dab, not the whole grid).
        /// </summary>
        public static ulong Combine(ulong seed, ulong[] blockHashes)
        {
            ulong h = seed ^ 0x9E3779B97F4A7C15UL;
            foreach (ulong b in blockHashes) h = Mix(h, b);
            return h;
        }

        /// <summary><see cref="BlockHash"/> of every block.</summary>
        public static ulong[] BlockHashes(double[][] blocks)
        {
            var hashes = new ulong[blocks.Length];
            for (int b = 0; b < blocks.Length; b++) hashes[b] = BlockHash(blocks[b]);
            return hashes;
        }

        /// <summary>Hashes again the blocks holding <paramref name="patches"/> (ascending, an edit's), each once.</summary>
        public static void Rehash(ulong[] hashes, double[][] blocks, int[] patches)
        {
            int hashed = -1;
            foreach (int p in patches)
            {
                int b = BlockOf(p);
                if (b != hashed) hashes[hashed = b] = BlockHash(blocks[b]);
            }
        }

        /// <summary>A hash of one block's length and doubles (their bits); a missing block has its own.</summary>
        public static ulong BlockHash(double[] block)
        {
            if (block == null) return 0xFFFFFFFFFFFFFFFFUL;
            ulong h = Mix(0, (ulong)block.Length);
            for (int k = 0; k < block.Length; k++) h = Mix(h, (ulong)BitConverter.DoubleToInt64Bits(block[k]));
            return h;
        }

        /// <summary>
        /// The blocks of <paramref name="next"/> that differ from <paramref name="current"/> (new, of
        /// another length, or any double of other bits), ascending: what a whole-grid replacement must
        /// write and record for Undo. The rest already hold those bits.
        /// </summary>
        public static int[] ChangedBlocks(double[][] current, double[][] next)
        {
            var changed = new List<int>();
            for (int b = 0; b < next.Length; b++)
                if (current == null || b >= current.Length || !SameBits(current[b], next[b])) changed.Add(b);
            return changed.ToArray();
        }

        static bool SameBits(double[] a, double[] b)
        {
            if (a == null || b == null || a.Length != b.Length) return false;
            for (int k = 0; k < a.Length; k++)
                if (BitConverter.DoubleToInt64Bits(a[k]) != BitConverter.DoubleToInt64Bits(b[k])) return false;
            return true;
        }

        /// <summary>One step of a multiply-xorshift hash (not cryptographic: it tells edits apart, it does not resist forgery).</summary>
        public static ulong Mix(ulong h, ulong v)
        {
            h ^= v + 0x9E3779B97F4A7C15UL + (h << 6) + (h >> 2);
            h *= 0xBF58476D1CE4E5B9UL;
            return h ^ (h >> 31);
        }

        /// <summary>Slots 0..15 on the border of the 4 x 4 net (i or j is 0 or 3), slot = 4 i + j.</summary>
        public static bool IsBoundarySlot(int slot) => slot < 16 && (slot / 4 == 0 || slot / 4 == 3 || slot % 4 == 0 || slot % 4 == 3);

        static int Offset(int patch, int slot) => (patch % PatchesPerBlock) * DoublesPerPatch + 3 * slot;

        static void Write(double[][] blocks, int patch, int slot, Double3 q)
        {
            double[] a = blocks[patch / PatchesPerBlock];
            int k = Offset(patch, slot);
            a[k] = q.x; a[k + 1] = q.y; a[k + 2] = q.z;
        }

        static bool SameBits(Double3 a, Double3 b) =>
            BitConverter.DoubleToInt64Bits(a.x) == BitConverter.DoubleToInt64Bits(b.x) &&
            BitConverter.DoubleToInt64Bits(a.y) == BitConverter.DoubleToInt64Bits(b.y) &&
            BitConverter.DoubleToInt64Bits(a.z) == BitConverter.DoubleToInt64Bits(b.z);

        static void CheckPoint(int columns, int rows, int patch, int slot)
        {
            if (columns < 1 || rows < 1) throw new ArgumentOutOfRangeException(nameof(columns), $"grid {columns} x {rows} must have at least one patch");
            if (patch < 0 || patch >= columns * rows)
                throw new ArgumentOutOfRangeException(nameof(patch), patch, $"patch must lie in [0, {columns * rows})");
            if (slot < 0 || slot >= GregoryPatch.SlotCount)
                throw new ArgumentOutOfRangeException(nameof(slot), slot, $"slot must lie in [0, {GregoryPatch.SlotCount})");
        }
    }
}
