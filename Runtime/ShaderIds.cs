using System;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// Every name the package's C# shares with its shaders, written once: material and compute
    /// properties (looked up once with Shader.PropertyToID, never a string per frame), buffers and
    /// kernels; the keywords are Core's <see cref="ShaderKeywords"/>. The TerrainParams constants are named by Core's
    /// <see cref="TerrainParams.PropertyNames"/> (generated); everything else is named here.
    /// ShaderContractTests checks this list against the shaders' declarations, both ways, and that no
    /// other Runtime or Editor file spells a shader name.
    /// </summary>
    internal static class ShaderIds
    {
        // ---- the terrain (TerrainInputs.hlsl): buffers sent once per grid, then TerrainParams -------

        public static readonly int ControlPoints = Shader.PropertyToID("_ControlPoints");
        public static readonly int Regions = Shader.PropertyToID("_Regions");
        public static readonly int GridLines = Shader.PropertyToID("_GridLines");
        /// <summary>The tiled noise's cell table (GT_NOISE_TABLE): Core's <see cref="GradientNoiseTable"/>, sent once.</summary>
        public static readonly int NoiseCells = Shader.PropertyToID("_NoiseCells");

        /// <summary><c>Params[k]</c> is the ID of TerrainParams float4 k (cbuffer order).</summary>
        public static readonly int[] Params = Array.ConvertAll(TerrainParams.PropertyNames, Shader.PropertyToID);

        /// <summary>The constants set on their own: the range (per frame), its origin (on re-snap), the tile lattice.</summary>
        public static readonly int Range = ParamId("_Range");
        public static readonly int RangeOrigin = ParamId("_RangeOrigin");
        public static readonly int TileLattice = ParamId("_TileLattice");

        /// <summary>The renderer's object matrices (the Unity adapters; deep-zoom offset included).</summary>
        public static readonly int ObjectToWorld = Shader.PropertyToID("_GtObjectToWorld");
        public static readonly int WorldToObject = Shader.PropertyToID("_GtWorldToObject");
        /// <summary>The drawing camera's object -> clip and pixel size (UnityAdapterCommon.hlsl).</summary>
        public static readonly int TessObjectToClip = Shader.PropertyToID("_GtTessObjectToClip");
        public static readonly int TessScreenSize = Shader.PropertyToID("_GtTessScreenSize");

        // ---- vertex cache (VertexCacheKernels.hlsl, LodCameraComputeAdapter.hlsl) --------------------

        public static readonly int TileFactors = Shader.PropertyToID("_TileFactors");
        public static readonly int VertexCache = Shader.PropertyToID("_VertexCache");
        public static readonly int TileFactorsRW = Shader.PropertyToID("_TileFactorsRW");
        public static readonly int VertexCacheRW = Shader.PropertyToID("_VertexCacheRW");
        public static readonly int TileCellsRW = Shader.PropertyToID("_TileCellsRW");
        public static readonly int LodObjectToClip = Shader.PropertyToID("_GT_LodObjectToClip");
        public static readonly int LodScreenSize = Shader.PropertyToID("_GT_LodScreenSize");
        public const string CacheFactorsKernel = "CacheTileFactors";
        public const string CacheVerticesKernel = "CacheTileVertices";

        // ---- snow (SnowSimulation.compute, SnowField.compute, TerrainInputs.hlsl's GT_SNOW part) -----

        /// <summary><c>SnowParams[k]</c> is the ID of SnowParams float4 k (cbuffer order; Core's <see cref="GregoryTerrain.SnowParams.PropertyNames"/>, generated).</summary>
        public static readonly int[] SnowParams = Array.ConvertAll(GregoryTerrain.SnowParams.PropertyNames, Shader.PropertyToID);
        public static readonly int SnowField = Shader.PropertyToID("_SnowField");
        public static readonly int SnowExposure = Shader.PropertyToID("_SnowExposure");
        public static readonly int SnowDepth = Shader.PropertyToID("_SnowDepth");
        public static readonly int SnowMapSize = Shader.PropertyToID("_SnowMapSize");
        /// <summary>Horizon levels (GT_LOD): <c>(L, kernel factors 0/1, 0, 0)</c>, and level k's range, sent per camera.</summary>
        public static readonly int LodLevels = Shader.PropertyToID("_LodLevels");
        public static readonly int Ranges = Shader.PropertyToID("_Ranges");
        /// <summary>The levels' factor kernels' records (LevelFactorKernels.hlsl): the hull's <c>_LodFactors</c>, the kernels' <c>_LodFactorsRW</c>.</summary>
        public static readonly int LodFactors = Shader.PropertyToID("_LodFactors");
        public static readonly int LodFactorsRW = Shader.PropertyToID("_LodFactorsRW");
        public const string LodFactorPiecesKernel = "LodFactorPieces";
        public const string LodFactorSeamsKernel = "LodFactorSeams";
        /// <summary>The levels' vertex cache kernels (LevelVertexCacheKernels.hlsl): records into <c>_VertexCacheRW</c>, the domain stage's <c>_VertexCache</c>.</summary>
        public const string LodVertexSlotsKernel = "LodVertexSlots";
        public const string LodCacheVerticesKernel = "LodCacheVertices";
        public const string SnowExposureKernel = "SnowExposureKernel";
        public const string SnowAccumulateKernel = "SnowAccumulateKernel";
        public const string SnowFieldKernel = "SnowFieldKernel";

        // A name of the TerrainParams block, checked against Core's list when this class loads.
        static int ParamId(string name)
        {
            if (Array.IndexOf(TerrainParams.PropertyNames, name) < 0)
                throw new InvalidOperationException($"TerrainParams.PropertyNames has no '{name}'");
            return Shader.PropertyToID(name);
        }

        /// <summary>Sets the whole TerrainParams block on a compute shader, each float4 by its name.</summary>
        public static void SetParams(ComputeShader shader, in TerrainParams p) => SetFloat4s(shader, Params, p);

        /// <summary>Sets a contract block (TerrainParams, SnowParams) on a compute shader, float4 k by ids[k].</summary>
        public static void SetFloat4s<T>(ComputeShader shader, int[] ids, in T block) where T : struct, IFloat4Block
        {
            for (int k = 0; k < ids.Length; k++)
            {
                Float4 v = block[k];
                shader.SetVector(ids[k], new Vector4(v.x, v.y, v.z, v.w));
            }
        }
    }
}
