using System;

namespace GregoryTerrain
{
    /// <summary>The four boundary edges of a patch: u = 0, u = 1 (parameter v), v = 0, v = 1 (parameter u).</summary>
    internal enum PatchSide { U0, U1, V0, V1 }

    /// <summary>
    /// Which slots lie on an edge and next to it. Along edge <c>side</c>, point k (0..3, in the
    /// direction of increasing edge parameter) is <see cref="EdgeSlot"/>; the point one step inwards
    /// is <see cref="InnerSlot"/>. For k = 1, 2 that is the interior point the edge's cross-boundary
    /// derivative uses: on u = const edges the second point of a pair (slots 16..19, since
    /// <c>t = a/(a+b)</c> is 0 there), on v = const edges the first (5, 6, 9, 10).
    /// The cross-boundary vector <c>D_k = P[InnerSlot] - P[EdgeSlot]</c> gives
    /// <c>dS/d(inwards) = 3 sum_k B3_k(t) D_k</c> on the edge.
    /// </summary>
    internal static class PatchEdge
    {
        static readonly int[][] Edge =
        {
            new[] { 0, 1, 2, 3 },     // U0: Slot(0, k)
            new[] { 12, 13, 14, 15 }, // U1: Slot(3, k)
            new[] { 0, 4, 8, 12 },    // V0: Slot(k, 0)
            new[] { 3, 7, 11, 15 },   // V1: Slot(k, 3)
        };

        static readonly int[][] Inner =
        {
            new[] { 4, GregoryPatch.P111, GregoryPatch.P121, 7 },  // U0: Slot(1, k)
            new[] { 8, GregoryPatch.P211, GregoryPatch.P221, 11 }, // U1: Slot(2, k)
            new[] { 1, GregoryPatch.P110, GregoryPatch.P210, 13 }, // V0: Slot(k, 1)
            new[] { 2, GregoryPatch.P120, GregoryPatch.P220, 14 }, // V1: Slot(k, 2)
        };

        public static int EdgeSlot(PatchSide side, int k) => Edge[Check(side)][CheckK(k)];
        public static int InnerSlot(PatchSide side, int k) => Inner[Check(side)][CheckK(k)];

        static int Check(PatchSide side)
        {
            if ((uint)side > 3u) throw new ArgumentOutOfRangeException(nameof(side), side, $"side = {side} is not a patch side.");
            return (int)side;
        }

        static int CheckK(int k)
        {
            if ((uint)k > 3u) throw new ArgumentOutOfRangeException(nameof(k), k, $"k = {k} must be in 0..3.");
            return k;
        }
    }
}
