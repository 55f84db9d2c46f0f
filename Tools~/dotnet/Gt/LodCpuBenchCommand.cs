using System;
using System.Diagnostics;
using System.Globalization;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli lod-cpu-bench: the CPU's work a frame for the Horizon levels, per camera, as the renderer
    /// does it (GregoryTerrainRenderer.Levels.cs: OriginRange, the origin tracker, PushLevels) with
    /// Core's code: LodLevels.Layout around the camera's ground point, RangeOriginTracker.Update with the
    /// finest level, RangeMapping.EncodeRange of every level into the preallocated float4s. For each
    /// terrain (100 km, 1,000 km) and camera (still; walking 1.5 m/s; flying 50 m/s; 60 frames a
    /// second) prints microseconds a frame (median of --rounds rounds of --frames frames), the bytes
    /// allocated a frame (GC.GetAllocatedBytesForCurrentThread) and the bytes the renderer sends a frame:
    /// <c>_Ranges</c> (SetVectorArray of LodTiles.MaxLevels float4, every frame), <c>_LodLevels</c> when
    /// the count changes and <c>_RangeOrigin</c> when the origin snaps again (16 bytes each). A
    /// benchmark, not a test: it prints, it asserts nothing.
    /// </summary>
    static class LodCpuBenchCommand
    {
        const int Tiles = 16;
        const double FramesPerSecond = 60;

        public static int Run(Args a)
        {
            int frames = a.Int("frames", 100000), rounds = a.Int("rounds", 7);
            Console.WriteLine($"# lod-cpu-bench: M = {Tiles}, finest level {GregoryTerrainRendererFinestMeters:G} m, {frames} frames a round, median of {rounds} rounds; .NET {Environment.Version}, {Environment.ProcessorCount} logical CPUs");
            foreach (double terrain in new[] { 100000.0, 1000000.0 })
                foreach (var (name, speed) in new[] { ("still", 0.0), ("walk", 1.5), ("fly", 50.0) })
                {
                    var cam = new LevelsCamera(terrain, speed);
                    cam.Frames(1000);   // warm-up: JIT and caches
                    var us = new double[rounds];
                    long allocated = 0, sent = 0;
                    for (int r = 0; r < rounds; r++)
                    {
                        long before = GC.GetAllocatedBytesForCurrentThread();
                        long start = Stopwatch.GetTimestamp();   // no Stopwatch object: nothing allocated inside the count
                        long bytes = cam.Frames(frames);
                        long ticks = Stopwatch.GetTimestamp() - start;
                        allocated += GC.GetAllocatedBytesForCurrentThread() - before;
                        sent += bytes;
                        us[r] = ticks * 1e6 / Stopwatch.Frequency / frames;
                    }
                    Array.Sort(us);
                    Console.WriteLine(FormattableString.Invariant(
                        $"lod_cpu {terrain / 1000:F0}km {name} levels {cam.Levels} us_per_frame {us[rounds / 2]:G4} allocated_bytes_per_frame {(double)allocated / ((long)frames * rounds):G3} bytes_sent_per_frame {(double)sent / ((long)frames * rounds):G5}"));
                }
            return 0;
        }

        /// <summary>The renderer's FinestLevelMeters (Runtime/GregoryTerrainRenderer.Levels.cs), which the rig does not compile.</summary>
        const double GregoryTerrainRendererFinestMeters = 16.0;

        /// <summary>One camera's state across frames, preallocated as the renderer holds it.</summary>
        sealed class LevelsCamera
        {
            readonly TerrainRange[] _ranges = new TerrainRange[LodTiles.MaxLevels];
            readonly Float4[] _vectors = new Float4[LodTiles.MaxLevels];
            readonly RangeOriginTracker _origin = new RangeOriginTracker();
            readonly int _finest;
            readonly double _unitsPerFrame;
            Double2 _ground = new Double2(0.37, 0.52);
            int _sentCount;
            public int Levels;

            public LevelsCamera(double terrainMeters, double metresPerSecond)
            {
                _finest = Math.Min(LodLevels.FinestExponent(terrainMeters, GregoryTerrainRendererFinestMeters), LodTiles.MaxLevels - 1);
                _unitsPerFrame = metresPerSecond / FramesPerSecond / terrainMeters;
            }

            /// <summary>Runs <paramref name="n"/> frames; returns the bytes sent.</summary>
            public long Frames(int n)
            {
                long bytes = 0;
                for (int f = 0; f < n; f++)
                {
                    _ground = new Double2(_ground.x, _ground.y + _unitsPerFrame);
                    if (_ground.y > 0.9) _ground = new Double2(_ground.x, 0.1);   // walk on, inside the terrain
                    int count = LodLevels.Layout(_ground, _finest, Tiles, _ranges);
                    if (_origin.Update(_ranges[0])) bytes += 16;                 // _RangeOrigin
                    for (int k = 0; k < count; k++)
                    {
                        RangeMapping.EncodeRange(_ranges[k], _origin.Origin, out Float4 r, out _);
                        _vectors[k] = r;
                    }
                    bytes += 16L * _vectors.Length;                               // _Ranges: the whole array
                    if (count != _sentCount) { _sentCount = count; bytes += 16; }  // _LodLevels
                    Levels = count;
                }
                return bytes;
            }
        }
    }
}
