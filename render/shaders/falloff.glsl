// falloff.glsl - included twice by scene.frag.glsl (@include): the body
// of both forms of hol_lights.
// The lights' falloff in GLSL, shared by hol_lights' two forms (HOL_V the
// type: vec4, the four slots at once, or float, one slot): from c2
// (the squared chord to each light) and dh (the height above the point) to
// d2 (the squared H2 x E distance, metres), num / den (the blended falloff)
// and w (the fade to 0 at HOL_LIGHT_RADIUS_M); sh and x (sinh and the floor
// distance) in hyperbolic programs, xm the floor distance in metres.
#if HOL_FLAT
  HOL_V d2 = c2 * HOL_KMPU2 + dh * dh;
  HOL_V xm = sqrt(c2 * HOL_KMPU2);
  HOL_V den = 1.0 + d2 * (1.0 / (HOL_LIGHT_D0_M * HOL_LIGHT_D0_M));
  HOL_V num = HOL_V(1.0);
#else
// s = x / sinh x as one quotient with the inverse square: (1 - B + B s)
// / (1 + d^2/D0^2) = ((1 - B) sh + B x) / (sh (1 + d^2/D0^2)), sh and x
// nudged by 1e-6 so that s is 1 at the light's foot
  HOL_V sh = sqrt(c2 + 0.25 * c2 * c2) + 1e-6;
  HOL_V x = log(1.0 + 0.5 * c2 + sh);
  HOL_V d2 = x * x * HOL_KMPU2 + dh * dh;
  HOL_V xm = x * sqrt(HOL_KMPU2);
  HOL_V num = (1.0 - HOL_LIGHT_PHYS) * sh + HOL_LIGHT_PHYS * x;
  HOL_V den = sh * (1.0 + d2 * (1.0 / (HOL_LIGHT_D0_M * HOL_LIGHT_D0_M)));
#endif
  HOL_V w = max(1.0 - d2 * (1.0 / (HOL_LIGHT_RADIUS_M * HOL_LIGHT_RADIUS_M)), 0.0);
