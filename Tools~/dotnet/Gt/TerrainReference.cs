using System;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// The exact surface the shaders approximate, in double (Core's reference pieces): tess
    /// coordinate of a drawn patch -> global point q -> Gregory patch (FindPatch, corrected eq. 10)
    /// -> GregoryEval + OctaveNoise on the height -> object space (x, z, y). The octave count is the
    /// one the GPU uses for this frame (OctaveCount of the range width and the vertex budget), so the
    /// error measures the tessellation, not the octaves left out on purpose.
    /// </summary>
    sealed class TerrainReference
    {
        readonly PatchGrid _grid;
        readonly TerrainRange _range;
        readonly int _tiles;
        readonly bool _paperMode;
        readonly NoiseSettings _noise;
        readonly double _octaves;

        /// <param name="octaves">the octave count (0: no noise, the GT_NOISE keyword off).</param>
        public TerrainReference(PatchGrid grid, TerrainRange range, int tiles, bool paperMode, NoiseSettings noise, double octaves)
        {
            _grid = grid ?? throw new ArgumentNullException(nameof(grid));
            range.Validate();
            if (tiles < 1) throw new ArgumentException($"tiles ({tiles}) must be >= 1", nameof(tiles));
            if (double.IsNaN(octaves) || octaves < 0) throw new ArgumentException($"octaves ({octaves}) must be >= 0", nameof(octaves));
            _range = range; _tiles = tiles; _paperMode = paperMode; _noise = noise; _octaves = octaves;
        }

        /// <summary>The octave count the shader uses (TerrainVertex.hlsl): OctaveCount(range width, verticesAcross).</summary>
        public static double ShaderOctaves(TerrainRange range, NoiseSettings noise, int tiles, double maxFactor, double noiseVertices) =>
            OctaveNoise.OctaveCount(range.Width, noiseVertices > 0 ? noiseVertices : tiles * maxFactor, noise);

        /// <summary>Object-space point (x, height, y) at tess coordinate (s, t) of drawn patch <paramref name="drawPatch"/>.</summary>
        public double[] ObjectPoint(int drawPatch, double s, double t)
        {
            double qx, qy;
            int patch;
            if (_paperMode)
            {
                qx = _range.c + s * _range.Width;
                qy = _range.d + t * _range.Height;
                patch = drawPatch;
            }
            else
            {
                int ti = drawPatch % _tiles, tj = drawPatch / _tiles;
                qx = _range.c + (ti + s) / _tiles * _range.Width;
                qy = _range.d + (tj + t) / _tiles * _range.Height;
                patch = _grid.FindPatch(qx, qy);
            }
            Region r = _grid.RegionOf(patch);
            Double2 uv = RangeMapping.LocalCoordinate(new Double2(qx, qy), r);
            if (_paperMode)
            {
                // u, v clamped: the part of the range outside the patch collapses onto its border, and
                // takes the noise of that border point.
                uv = new Double2(Math.Clamp(uv.x, 0, 1), Math.Clamp(uv.y, 0, 1));
                qx = r.a + uv.x * (r.e - r.a);
                qy = r.b + uv.y * (r.f - r.b);
            }
            Double3 p = GregoryEval.Position(_grid.Patches[patch].Points, uv.x, uv.y);
            double z = p.z;
            if (_octaves > 0) z += OctaveNoise.Evaluate(qx, qy, _noise, _octaves, out _);
            return new[] { p.x, z, p.y };
        }
    }
}
