// Constants of the shading kernel.
const real kPi = 3.14159265358979323846;
const real kTwoPi = 6.28318530717958647693;
const real kInvTwoPi = 0.15915494309189533577;
const real kSqrtTwo = 1.41421356237309504880;
const real kInvSqrtTwo = 0.70710678118654752440;
const real kInvSqrtPi = 0.56418958354775628695;
const real kInvSqrtTwoPi = 0.39894228040143267794;
const real kSqrtHalfPi = 1.25331413731550025121;  // sqrt(pi / 2)
// Schlick's R0 for water (scene spec: fresnel "schlick").
const real kSchlickR0 = 0.02;
