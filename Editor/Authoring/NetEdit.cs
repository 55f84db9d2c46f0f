using System;
using System.Collections.Generic;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// The engine under <see cref="PatchBrush"/> and <see cref="PatchRegionFit"/>: a window of a grid's
    /// patches, copied, edited as the height net of their control points, made G1 again around what
    /// changed, and handed back as a <see cref="PatchEdit"/> (the grid itself is never written).
    /// <para><b>The net.</b> Node (a, b) is slot <c>(a - 3i, b - 3j)</c> of patch (i, j); a shared
    /// node is stored in every patch sharing it and <see cref="SetNodeZ"/> writes all copies with the
    /// same bits. The pairs' second points (16..19) are set per patch (<see cref="SetZ"/>). Edits
    /// change z only.</para>
    /// <para><b>G1 again, locally.</b> <see cref="RepairCorners"/> puts each vertex back on one line
    /// with its boundary neighbours; <see cref="JoinEdges"/> rejoins only the edges whose inputs
    /// changed, so patches further out keep every bit.</para>
    /// </summary>
    internal sealed class NetEdit
    {
        readonly PatchGrid _grid;
        readonly int _wi0, _wj0, _wi1, _wj1, _wc;
        readonly GregoryPatch[] _patches;   // window copies, local index (j - wj0) * wc + (i - wi0)
        readonly bool[] _changed;           // local patch * 20 + slot

        /// <summary>Copies the window's patches; throws ArgumentException if they are not finite or do not share their edges bit for bit.</summary>
        public NetEdit(PatchGrid grid, PatchRect window)
        {
            _grid = grid ?? throw new ArgumentNullException(nameof(grid));
            window.Check(grid.Columns, grid.Rows, "window");
            _wi0 = window.I0; _wj0 = window.J0; _wi1 = window.I1; _wj1 = window.J1; _wc = window.Columns;
            _patches = new GregoryPatch[window.PatchCount];
            _changed = new bool[window.PatchCount * GregoryPatch.SlotCount];
            for (int j = _wj0; j <= _wj1; j++)
                for (int i = _wi0; i <= _wi1; i++)
                {
                    GregoryPatch p = grid.Patch(i, j);
                    p.Validate(Name(i, j));
                    _patches[Local(i, j)] = p.Clone();
                    if (i < _wi1) for (int k = 0; k < 4; k++) CheckShared(i, j, GregoryPatch.Slot(3, k), i + 1, j, GregoryPatch.Slot(0, k));
                    if (j < _wj1) for (int k = 0; k < 4; k++) CheckShared(i, j, GregoryPatch.Slot(k, 3), i, j + 1, GregoryPatch.Slot(k, 0));
                }
        }

        public PatchGrid Grid => _grid;

        int Local(int i, int j)
        {
            if (i < _wi0 || i > _wi1 || j < _wj0 || j > _wj1)
                throw new InvalidOperationException(F("patch ({0}, {1}) is outside the edit's window (columns {2}..{3}, rows {4}..{5}).", i, j, _wi0, _wi1, _wj0, _wj1));
            return (j - _wj0) * _wc + (i - _wi0);
        }

        /// <summary>The window's copy of patch (i, j).</summary>
        public GregoryPatch Patch(int i, int j) => _patches[Local(i, j)];

        /// <summary>Node (a, b) (any copy: they are identical).</summary>
        public Double3 Node(int a, int b)
        {
            Owner(a, out int i, out int ka, _wi0, _wi1);
            Owner(b, out int j, out int kb, _wj0, _wj1);
            return Patch(i, j)[GregoryPatch.Slot(ka, kb)];
        }

        static void Owner(int a, out int i, out int k, int lo, int hi)
        {
            i = Math.Max(lo, Math.Min(a / 3, hi));
            k = a - 3 * i;
            if (k < 0 || k > 3) throw new InvalidOperationException(F("net node {0} is outside the edit's window.", a));
        }

        /// <summary>True when any copy of node (a, b) has changed.</summary>
        public bool NodeChanged(int a, int b)
        {
            bool any = false;
            ForEachCopy(a, b, (i, j, s) => any |= _changed[Local(i, j) * GregoryPatch.SlotCount + s]);
            return any;
        }

        /// <summary>Sets node (a, b)'s height in every patch sharing it, the same bits in each.</summary>
        public void SetNodeZ(int a, int b, double z) => ForEachCopy(a, b, (i, j, s) => SetZ(i, j, s, z));

        /// <summary>Sets the height of slot <paramref name="slot"/> of patch (i, j) alone (for the pairs' second points).</summary>
        public void SetZ(int i, int j, int slot, double z)
        {
            int l = Local(i, j);
            Double3 p = _patches[l][slot];
            if (BitConverter.DoubleToInt64Bits(p.z) == BitConverter.DoubleToInt64Bits(z)) return;
            _patches[l][slot] = new Double3(p.x, p.y, z);
            _changed[l * GregoryPatch.SlotCount + slot] = true;
        }

        void ForEachCopy(int a, int b, Action<int, int, int> visit)
        {
            int n = _grid.Columns, m = _grid.Rows;
            for (int i = a % 3 == 0 ? a / 3 - 1 : a / 3; i <= a / 3; i++)
            {
                if (i < 0 || i >= n) continue;
                for (int j = b % 3 == 0 ? b / 3 - 1 : b / 3; j <= b / 3; j++)
                {
                    if (j < 0 || j >= m) continue;
                    visit(i, j, GregoryPatch.Slot(a - 3 * i, b - 3 * j));   // Local() throws for a copy outside the window
                }
            }
        }

        /// <summary>
        /// At each grid vertex (I, J) of the range whose star (the vertex and the four boundary points
        /// next to it) changed, puts the star back on two lines (x on an interior vertical line, y on an
        /// interior horizontal one) by the least change, in the sum of squares, of the editable points'
        /// heights. The vertex moves too: held fixed, a peak on a vertex could never be smoothed down.
        /// </summary>
        public void RepairCorners(int vi0, int vj0, int vi1, int vj1, Func<int, int, bool> editable)
        {
            int n = _grid.Columns, m = _grid.Rows;
            for (int J = vj0; J <= vj1; J++)
                for (int I = vi0; I <= vi1; I++)
                {
                    int a = 3 * I, b = 3 * J;
                    bool starChanged = NodeChanged(a, b)
                        || (I > 0 && NodeChanged(a - 1, b)) || (I < n && NodeChanged(a + 1, b))
                        || (J > 0 && NodeChanged(a, b - 1)) || (J < m && NodeChanged(a, b + 1));
                    if (starChanged) Straighten(a, b, I > 0 && I < n, J > 0 && J < m, editable);
                }
        }

        /// <summary>
        /// Star nodes 0..4 = centre, -x, +x, -y, +y. Constraint c is <c>g_c . z = 0</c> with
        /// <c>g = (-1, tr/(tl+tr), tl/(tl+tr))</c>; the weighted projection <c>z -= W G^T (G W G^T)^-1 G z</c>,
        /// W = 1 on editable nodes, 0 on fixed. A constraint with no editable node is left as it is.
        /// </summary>
        void Straighten(int a, int b, bool alongX, bool alongY, Func<int, int, bool> editable)
        {
            if (!alongX && !alongY) return;
            int[] na = { a, a - 1, a + 1, a, a }, nb = { b, b, b, b - 1, b + 1 };
            var z = new double[5];
            var w = new double[5];
            var g = new double[2, 5];
            int count = 0;
            Double3 c = Node(a, b);
            z[0] = c.z;
            w[0] = editable(a, b) ? 1 : 0;
            for (int axis = 0; axis < 2; axis++)
            {
                if (axis == 0 ? !alongX : !alongY) continue;
                int lo = 1 + 2 * axis, hi = 2 + 2 * axis;
                Double3 l = Node(na[lo], nb[lo]), r = Node(na[hi], nb[hi]);
                double tl = Math.Sqrt((c.x - l.x) * (c.x - l.x) + (c.y - l.y) * (c.y - l.y));
                double tr = Math.Sqrt((r.x - c.x) * (r.x - c.x) + (r.y - c.y) * (r.y - c.y));
                if (!(tl > 0) || !(tr > 0))
                    throw new ArgumentException(F("grid: the boundary points next to net node ({0}, {1}) coincide with it in x, y: no slope to keep.", a, b), "grid");
                z[lo] = l.z; z[hi] = r.z;
                w[lo] = editable(na[lo], nb[lo]) ? 1 : 0;
                w[hi] = editable(na[hi], nb[hi]) ? 1 : 0;
                double gw = w[0] + w[lo] * tr * tr / ((tl + tr) * (tl + tr)) + w[hi] * tl * tl / ((tl + tr) * (tl + tr));
                if (!(gw > 0)) continue;   // nothing here may move
                g[count, 0] = -1; g[count, lo] = tr / (tl + tr); g[count, hi] = tl / (tl + tr);
                count++;
            }
            if (count == 0) return;
            // M = G W G^T (count x count), rhs = G z.
            double m00 = 0, m01 = 0, m11 = 0, r0 = 0, r1 = 0;
            for (int k = 0; k < 5; k++)
            {
                m00 += g[0, k] * w[k] * g[0, k];
                m01 += g[0, k] * w[k] * g[1, k];
                m11 += g[1, k] * w[k] * g[1, k];
                r0 += g[0, k] * z[k];
                r1 += g[1, k] * z[k];
            }
            double l0, l1;
            if (count == 1) { l0 = r0 / m00; l1 = 0; }
            else
            {
                double det = m00 * m11 - m01 * m01;
                if (!(Math.Abs(det) > 1e-12 * m00 * m11))
                {
                    // Both lines hang on the centre alone: one fixes it; the other holds only if it held before.
                    l0 = r0 / m00; l1 = 0;
                }
                else { l0 = (r0 * m11 - r1 * m01) / det; l1 = (r1 * m00 - r0 * m01) / det; }
            }
            for (int k = 0; k < 5; k++)
            {
                if (w[k] == 0) continue;
                double dz = w[k] * (g[0, k] * l0 + g[1, k] * l1);
                if (dz != 0) SetNodeZ(na[k], nb[k], z[k] - dz);
            }
        }

        /// <summary>
        /// Rejoins G1 every shared edge whose inputs changed, <paramref name="rule"/>(i, j, vertical)
        /// choosing which side keeps its interior points ((i, j) the low patch). Throws
        /// InvalidOperationException if such an edge reaches outside the window (a bug, not bad input).
        /// </summary>
        public void JoinEdges(Func<int, int, bool, EdgeRule> rule, double relativeTolerance = 1e-9)
        {
            int n = _grid.Columns, m = _grid.Rows;
            var edges = new List<SharedEdge>();
            var where = new List<(int i, int j, bool vertical)>();
            for (int j = Math.Max(0, _wj0 - 1); j <= _wj1; j++)
                for (int i = Math.Max(0, _wi0 - 1); i <= _wi1; i++)
                    for (int v = 0; v < 2; v++)
                    {
                        bool vertical = v == 0;
                        int hi = vertical ? i + 1 : i, hj = vertical ? j : j + 1;
                        if (hi >= n || hj >= m) continue;
                        bool lowIn = InWindow(i, j), highIn = InWindow(hi, hj);
                        if (!lowIn && !highIn) continue;
                        PatchSide ls = vertical ? PatchSide.U1 : PatchSide.V1, hs = vertical ? PatchSide.U0 : PatchSide.V0;
                        bool changed = (lowIn && SideChanged(i, j, ls)) || (highIn && SideChanged(hi, hj, hs));
                        if (!changed) continue;
                        if (!lowIn || !highIn)
                            throw new InvalidOperationException(F("the edit changed the edge between patch ({0}, {1}) and patch ({2}, {3}), which leaves its window.", i, j, hi, hj));
                        edges.Add(new SharedEdge(Patch(i, j), Patch(hi, hj), vertical, rule(i, j, vertical),
                            F("edge between patch ({0}, {1}) and patch ({2}, {3})", i, j, hi, hj)));
                        where.Add((i, j, vertical));
                    }
            // Interior slots the joins write: remember them to flag what really changed.
            var before = new Double3[where.Count * 4];
            for (int e = 0; e < where.Count; e++) ForInner(where[e], (k, l, s) => before[4 * e + k] = _patches[l][s]);
            G1Builder.MakeG1Edges(edges, relativeTolerance);
            for (int e = 0; e < where.Count; e++)
                ForInner(where[e], (k, l, s) =>
                {
                    if (!SameBits(before[4 * e + k], _patches[l][s])) _changed[l * GregoryPatch.SlotCount + s] = true;
                });
        }

        void ForInner((int i, int j, bool vertical) e, Action<int, int, int> visit)
        {
            PatchSide ls = e.vertical ? PatchSide.U1 : PatchSide.V1, hs = e.vertical ? PatchSide.U0 : PatchSide.V0;
            int hi = e.vertical ? e.i + 1 : e.i, hj = e.vertical ? e.j : e.j + 1;
            visit(0, Local(e.i, e.j), PatchEdge.InnerSlot(ls, 1));
            visit(1, Local(e.i, e.j), PatchEdge.InnerSlot(ls, 2));
            visit(2, Local(hi, hj), PatchEdge.InnerSlot(hs, 1));
            visit(3, Local(hi, hj), PatchEdge.InnerSlot(hs, 2));
        }

        bool InWindow(int i, int j) => i >= _wi0 && i <= _wi1 && j >= _wj0 && j <= _wj1;

        bool SideChanged(int i, int j, PatchSide side)
        {
            int l = Local(i, j) * GregoryPatch.SlotCount;
            for (int k = 0; k < 4; k++)
                if (_changed[l + PatchEdge.EdgeSlot(side, k)] || _changed[l + PatchEdge.InnerSlot(side, k)]) return true;
            return false;
        }

        /// <summary>
        /// The changed patches as an edit, after checking each is finite and within float32's range
        /// (ArgumentException naming the patch, slot and value otherwise).
        /// </summary>
        public PatchEdit ToEdit()
        {
            var indices = new List<int>();
            var values = new List<GregoryPatch>();
            for (int j = _wj0; j <= _wj1; j++)
                for (int i = _wi0; i <= _wi1; i++)
                {
                    int l = Local(i, j);
                    bool any = false;
                    for (int s = 0; s < GregoryPatch.SlotCount; s++) any |= _changed[l * GregoryPatch.SlotCount + s];
                    if (!any) continue;
                    GregoryPatch p = _patches[l];
                    p.Validate(Name(i, j));
                    for (int s = 0; s < GregoryPatch.SlotCount; s++)
                        if (!InputLimits.FitsFloat(p[s].z))
                            throw new ArgumentException(F("the edit would put {0} slot {1} at height {2:R}, outside float32's range (|z| <= {3:R}).", Name(i, j), s, p[s].z, InputLimits.MaxFloat), "strength");
                    indices.Add(_grid.Index(i, j));
                    values.Add(p);
                }
            return new PatchEdit(_grid.Columns, _grid.Rows, indices.ToArray(), values.ToArray());
        }

        void CheckShared(int i0, int j0, int s0, int i1, int j1, int s1)
        {
            Double3 a = _grid.Patch(i0, j0)[s0], b = _grid.Patch(i1, j1)[s1];
            if (!SameBits(a, b))
                throw new ArgumentException(F("grid: {0} and {1} share an edge but slot {2} = {3} differs from slot {4} = {5}; shared boundary points must be identical (PatchGrid.Validate).",
                    Name(i0, j0), Name(i1, j1), s0, a, s1, b), "grid");
        }

        static bool SameBits(Double3 a, Double3 b) =>
            BitConverter.DoubleToInt64Bits(a.x) == BitConverter.DoubleToInt64Bits(b.x) &&
            BitConverter.DoubleToInt64Bits(a.y) == BitConverter.DoubleToInt64Bits(b.y) &&
            BitConverter.DoubleToInt64Bits(a.z) == BitConverter.DoubleToInt64Bits(b.z);

        static string Name(int i, int j) => F("patch ({0}, {1})", i, j);

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
