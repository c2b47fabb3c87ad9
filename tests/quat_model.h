/* quat_model.h - the tests' independent model of a rotation by a unit
 * quaternion (x, y, z, w), as its 3 x 3 matrix, for the XR tests
 * (test_xr_room.c, test_xr_quad.c). Header only, no state. */
#ifndef TESTS_QUAT_MODEL_H
#define TESTS_QUAT_MODEL_H

/* v rotated by unit quaternion q, as a matrix (the model) */
static inline void quat_model_rotate(const float q[4], const double v[3], double out[3])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    for (int i = 0; i < 3; i++)
        out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

#endif
