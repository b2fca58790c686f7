#pragma once
// A plain 3-vector for positions, velocities and forces in SI units. Kept as an
// aggregate so arrays of it can be handed to the solver and to LIGGGHTS as-is.

#include <cmath>

namespace spoutlab
{

struct Vec3
{
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;

    Vec3& operator+=(const Vec3& b)
    {
        x += b.x;
        y += b.y;
        z += b.z;
        return *this;
    }
    Vec3& operator-=(const Vec3& b)
    {
        x -= b.x;
        y -= b.y;
        z -= b.z;
        return *this;
    }
    Vec3& operator*=(double s)
    {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    Vec3& operator/=(double s)
    {
        x /= s;
        y /= s;
        z /= s;
        return *this;
    }
};

inline Vec3 operator+(Vec3 a, const Vec3& b)
{
    return a += b;
}
inline Vec3 operator-(Vec3 a, const Vec3& b)
{
    return a -= b;
}
inline Vec3 operator-(const Vec3& a)
{
    return {-a.x, -a.y, -a.z};
}
inline Vec3 operator*(Vec3 a, double s)
{
    return a *= s;
}
inline Vec3 operator*(double s, Vec3 a)
{
    return a *= s;
}
inline Vec3 operator/(Vec3 a, double s)
{
    return a /= s;
}

inline double dot(const Vec3& a, const Vec3& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double magSqr(const Vec3& a)
{
    return dot(a, a);
}
inline double mag(const Vec3& a)
{
    return std::sqrt(magSqr(a));
}

} // namespace spoutlab
