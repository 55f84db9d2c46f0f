using System;
using System.Runtime.InteropServices;

namespace GregoryTerrain
{
    /// <summary>
    /// The <c>TerrainParams</c> constants every stage reads (internals.md, "One contract to the
    /// GPU"): eleven float4, 176 bytes, blittable, declared here once. <c>gt generate</c> writes the HLSL
    /// members (Shaders/Terrain/TerrainParams.cs.hlsl, inside TerrainInputs.hlsl's cbuffer) and
    /// TerrainParams.Generated.cs (<see cref="PropertyNames"/>, <see cref="Float4Count"/>) from
    /// these fields, in their order. The rig uploads <see cref="Pack"/> as one block;
    /// Unity sets each float4 by name (the SRP Batcher wants named material constants). Only
    /// <see cref="range"/> changes per frame. Tools~/RigTests/ShaderContractTests compares this
    /// layout with the cbuffer the shader compiler lays out.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Terrain/TerrainParams.cs.hlsl", "Runtime/Core/Terrain/TerrainParams.Generated.cs")]
    internal partial struct TerrainParams : IFloat4Block
    {
        public const int Floats = Float4Count * 4;
        /// <summary>Size of the block: the cbuffer's size without the snow variant's <c>_SnowMapSize</c>.</summary>
        public const int Bytes = Floats * sizeof(float);

        // Instance fields only below, in cbuffer order: the layout is the declaration order.
        [HlslComment("(c, d, g, h) relative to the range origin        per frame")]
        public Float4 range;
        [HlslComment("(O.x hi, O.y hi, O.x lo, O.y lo)                  on re-snap")]
        public Float4 rangeOrigin;
        [HlslComment("(n columns, m rows, 0, 0)                         once")]
        public Float4 gridSize;
        [HlslComment("(tiles M, maxFactor, targetPixelError, uniform)   on change")]
        public Float4 tess;
        [HlslComment("(amplitude, frequency, alpha, beta)               on change")]
        public Float4 noise;
        [HlslComment("(octaves N, verticesAcross override or 0, LOD segment pixels or 0, LOD plain-path error or 0)")]
        public Float4 noiseOctaves;
        [HlslComment("(gamma, colorNoiseAmplitude, colorNoiseFrequency, 0)")]
        public Float4 heightColor;
        [HlslComment("C of eq. 15, linear RGB")]
        public Float4 colorLow;
        [HlslComment("B of eq. 15, linear RGB")]
        public Float4 colorHigh;

        /// <summary>
        /// <c>_TileLattice</c>: 0 (the default) lays the M x M tiles over the range, as the paper does;
        /// else the range, relative to the origin like <see cref="range"/>, at which the tiles were
        /// anchored to the terrain (internals.md, "Anchored tiles"): (M + 1)^2 tiles then follow the
        /// lattice of that range's tiles, clipped to the current range, so a pan moves only the
        /// clipped ones. Set with <see cref="WithTileLattice"/>.
        /// </summary>
        [HlslComment("0, or the range the tiles were anchored at (TileLattice.hlsl)  on anchoring")]
        public Float4 tileLattice;

        /// <summary><c>_OriginSurface</c>: the levels' S(O) and p(O) in float (<see cref="TerrainVertex.OriginSurface"/>), else 0.</summary>
        [HlslComment("levels: (S(O), p(O)) in float, the plain path's origin  on re-snap")]
        public Float4 originSurface;

        /// <summary>
        /// The renderer settings' one validation: throws ArgumentException naming the field, the value
        /// and the limit unless every setting can be drawn. The renderer and the controllers call it
        /// where a setting enters (OnValidate, setters); <see cref="Create"/> calls it too.
        /// </summary>
        public static void CheckSettings(TerrainRange range, TessellationSettings tessellation, NoiseSettings noise,
            HeightColorSettings heightColor, Float3 colorLow, Float3 colorHigh, float noiseVerticesAcross = 0f)
        {
            range.Validate();
            tessellation.Validate();
            noise.Validate();
            heightColor.Validate();
            if (!colorLow.IsFinite) throw new ArgumentException($"colorLow {colorLow} must be finite", nameof(colorLow));
            if (!colorHigh.IsFinite) throw new ArgumentException($"colorHigh {colorHigh} must be finite", nameof(colorHigh));
            if (!(noiseVerticesAcross >= 0f) || !GMath.isfinite(noiseVerticesAcross))
                throw new ArgumentException(FormattableString.Invariant($"noiseVerticesAcross ({noiseVerticesAcross:R}) must be finite and >= 0"), nameof(noiseVerticesAcross));
        }

        /// <summary>Validates every input (naming the field and value) and encodes the range against its origin.</summary>
        public static TerrainParams Create(PatchGrid grid, TerrainRange range, RangeOrigin origin,
            TessellationSettings tessellation, NoiseSettings noise, HeightColorSettings heightColor,
            Float3 colorLow, Float3 colorHigh, float noiseVerticesAcross = 0f)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            CheckSettings(range, tessellation, noise, heightColor, colorLow, colorHigh, noiseVerticesAcross);

            RangeMapping.EncodeRange(range, origin, out Float4 rangeF, out Float4 originF);
            float[] size = GpuLayout.GridSize(grid);
            return new TerrainParams
            {
                range = rangeF,
                rangeOrigin = originF,
                gridSize = new Float4(size[0], size[1], size[2], size[3]),
                tess = tessellation.ToFloat4(),
                noise = noise.ToFloat4(),
                noiseOctaves = new Float4(noise.octaves, noiseVerticesAcross, 0f, 0f),
                heightColor = heightColor.ToFloat4(),
                colorLow = new Float4(colorLow.x, colorLow.y, colorLow.z, 1f),
                colorHigh = new Float4(colorHigh.x, colorHigh.y, colorHigh.z, 1f),
            };
        }

        /// <summary>The float4 at cbuffer position <paramref name="index"/> (see <see cref="PropertyNames"/>).</summary>
        public Float4 this[int index] => Float4Block.At(ref this, index, Float4Count);

        /// <summary>Whether the tiles are anchored to the terrain (a nonzero <see cref="tileLattice"/>).</summary>
        public bool TilesAnchored => TileLattice.IsAnchored(tileLattice);

        /// <summary>
        /// These constants with <c>_TileLattice = lattice</c>: <see cref="Float4"/> 0 lays the tiles over
        /// the range; else a range (relative to the origin) with positive, finite widths that the
        /// current range fits in (<see cref="TileLattice.Validate"/>). Throws, naming the value, and
        /// changes nothing when it does not.
        /// </summary>
        public TerrainParams WithTileLattice(Float4 lattice)
        {
            TileLattice.Validate(lattice, range, tess.x, "tileLattice");
            TerrainParams p = this;
            p.tileLattice = lattice;
            return p;
        }

        /// <summary>The 4 x Float4Count floats of the cbuffer, in order: the struct's own bytes, so Pack cannot disagree with the layout.</summary>
        public float[] Pack() => Float4Block.Pack(this);
    }
}
