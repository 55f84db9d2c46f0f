using System;

namespace GregoryTerrain
{
    /// <summary>
    /// What the snow simulation reads of the terrain: an R x R grid over the terrain's unit square,
    /// one float4 per cell, <c>(detail normal.xyz, height z)</c>, in the layout of the GPU buffer
    /// <c>_SnowField</c>. Cell <c>(i, j)</c> is at <c>j * R + i</c> and stands for the point
    /// <c>((i + 0.5) / R, (j + 0.5) / R)</c>. The normal is the upward unit <i>detail</i> normal
    /// (patch normal plus noise detail): the paper's <c>N_m</c>, whose small-scale tilt is what lets a
    /// steep face catch snow at all. On the GPU the terrain evaluation fills it; on the CPU anything may.
    /// <para><see cref="Version"/> goes up on every change, so the simulation knows when exposure is stale.</para>
    /// </summary>
    public sealed class SnowField
    {
        /// <summary>Cells per side, R (a power of two from 64 to 4096).</summary>
        public int Resolution { get; }
        /// <summary>4 floats per cell: nx, ny, nz, height. Call <see cref="MarkChanged"/> after writing it directly.</summary>
        public float[] Data { get; }
        /// <summary>Changes whenever the contents may have changed.</summary>
        public int Version { get; private set; }

        /// <summary>A level field of R x R cells (normal straight up, height 0). Throws ArgumentException unless R is a power of two from 64 to 4096.</summary>
        public SnowField(int resolution)
        {
            if (resolution < SnowSettings.MinResolution || resolution > SnowSettings.MaxResolution || (resolution & (resolution - 1)) != 0)
                throw new ArgumentException(FormattableString.Invariant(
                    $"resolution ({resolution}) must be a power of two from 64 to 4096"), nameof(resolution));
            Resolution = resolution;
            Data = new float[4 * resolution * resolution];
            for (int k = 0; k < resolution * resolution; k++) Data[4 * k + 2] = 1f;  // level ground at z = 0
        }

        /// <summary>Centre of cell (i, j) in terrain space; the same float arithmetic as the shaders.</summary>
        public Float2 CellCentre(int i, int j)
        {
            float inv = 1f / Resolution;  // exact: R is a power of two
            return new Float2((i + 0.5f) * inv, (j + 0.5f) * inv);
        }

        /// <summary>Height of cell (i, j).</summary>
        public float Height(int i, int j) => Data[4 * (j * Resolution + i) + 3];
        /// <summary>Detail normal of cell (i, j).</summary>
        public Float3 Normal(int i, int j) { int k = 4 * (j * Resolution + i); return new Float3(Data[k], Data[k + 1], Data[k + 2]); }

        /// <summary>Sets one cell. The normal must be finite (it is used as given: pass a unit vector).</summary>
        public void Set(int i, int j, Float3 normal, float height)
        {
            if ((uint)i >= (uint)Resolution || (uint)j >= (uint)Resolution)
                throw new ArgumentException(FormattableString.Invariant($"cell ({i}, {j}) is outside the {Resolution} x {Resolution} field"), nameof(i));
            if (!normal.IsFinite) throw new ArgumentException($"normal ({normal}) must be finite", nameof(normal));
            if (!GMath.isfinite(height)) throw new ArgumentException(FormattableString.Invariant($"height ({height:R}) must be finite"), nameof(height));
            int k = 4 * (j * Resolution + i);
            Data[k] = normal.x; Data[k + 1] = normal.y; Data[k + 2] = normal.z; Data[k + 3] = height;
            Version++;
        }

        /// <summary>Records a change made through <see cref="Data"/>.</summary>
        public void MarkChanged() => Version++;
    }
}
