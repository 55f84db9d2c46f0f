using System;

namespace GregoryTerrain
{
    /// <summary>
    /// HLSL's intrinsics for Core, so that C# that mirrors a shader reads like it
    /// (<c>using static GregoryTerrain.GMath;</c>). Float overloads round every step to float,
    /// as the GPU does; double overloads are the reference.
    /// </summary>
    internal static class GMath
    {
        public static bool isfinite(float a) => !float.IsNaN(a) && !float.IsInfinity(a);
        public static bool isfinite(double a) => !double.IsNaN(a) && !double.IsInfinity(a);

        public static float saturate(float a) => a < 0f ? 0f : (a > 1f ? 1f : a);
        public static double saturate(double a) => a < 0.0 ? 0.0 : (a > 1.0 ? 1.0 : a);

        public static float clamp(float a, float lo, float hi) => a < lo ? lo : (a > hi ? hi : a);
        public static double clamp(double a, double lo, double hi) => a < lo ? lo : (a > hi ? hi : a);

        public static float lerp(float a, float b, float t) => a + t * (b - a);
        public static double lerp(double a, double b, double t) => a + t * (b - a);
        public static Float2 lerp(Float2 a, Float2 b, float t) => a + t * (b - a);
        public static Float3 lerp(Float3 a, Float3 b, float t) => a + t * (b - a);
        public static Double3 lerp(Double3 a, Double3 b, double t) => a + t * (b - a);

        public static float floor(float a) => (float)Math.Floor(a);
        public static double floor(double a) => Math.Floor(a);
        public static float frac(float a) => a - floor(a);
        public static double frac(double a) => a - floor(a);
        public static float sqrt(float a) => (float)Math.Sqrt(a);
        /// <summary>1 / sqrt(a), rounded once; a GPU's rsqrt is within a few ulp of it.</summary>
        public static float rsqrt(float a) => (float)(1.0 / Math.Sqrt(a));

        public static float dot(Float3 a, Float3 b) => a.x * b.x + a.y * b.y + a.z * b.z;
        public static double dot(Double3 a, Double3 b) => a.x * b.x + a.y * b.y + a.z * b.z;
        public static float dot(Float2 a, Float2 b) => a.x * b.x + a.y * b.y;
        public static double dot(Double2 a, Double2 b) => a.x * b.x + a.y * b.y;

        public static Float3 cross(Float3 a, Float3 b) =>
            new Float3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
        public static Double3 cross(Double3 a, Double3 b) =>
            new Double3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);

        public static float length(Float3 a) => (float)Math.Sqrt(dot(a, a));
        public static double length(Double3 a) => Math.Sqrt(dot(a, a));
        public static double length(Double2 a) => Math.Sqrt(dot(a, a));

        /// <summary>Unit vector; the zero vector stays zero rather than becoming NaN.</summary>
        public static Float3 normalize(Float3 a)
        {
            float l = length(a);
            return l > 0f ? a / l : Float3.zero;
        }

        /// <summary>Unit vector; the zero vector stays zero rather than becoming NaN.</summary>
        public static Double3 normalize(Double3 a)
        {
            double l = length(a);
            return l > 0.0 ? a / l : Double3.zero;
        }
    }
}
