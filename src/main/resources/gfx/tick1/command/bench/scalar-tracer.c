/*
 * The benchmark's yardstick for a big render: a plain, single-threaded, scalar C tracer of the
 * same scene with the same maths in doubles as tick1 (the handout's quadratic for each sphere,
 * Phong shading as Renderer.illuminate computes it, the same sample offsets, the mean of the
 * samples and the course's truncating conversion to bytes), one pixel at a time.
 *
 * Built and run by `tick1 bench` where a C compiler is present:
 *
 *     cc -O3 -ffp-contract=off -o scalar-tracer scalar-tracer.c -lm
 *     ./scalar-tracer SCENE.txt IMAGE.ppm
 *
 * (-ffp-contract=off: no fused multiply-adds, which would round differently from Java.)
 *
 * SCENE.txt is written by the benchmark from the loaded scene, every number in hexadecimal
 * floating point so that it carries the exact bits:
 *
 *     width height samples
 *     widthM                              the camera's image plane width, 2 tan(45 degrees / 2)
 *     dx dy                               one line per sample: its offset in the pixel
 *     ambientRed ambientGreen ambientBlue
 *     lit lightX lightY lightZ lightRed lightGreen lightBlue intensity
 *     spheres
 *     cx cy cz radius red green blue kD kS n   one line per sphere, in file order
 *
 * The image goes to IMAGE.ppm (binary PPM), so that the benchmark can check that it holds the
 * pixels tick1 draws, and so that no compiler can drop the work as unused.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
    double cx, cy, cz, radius, red, green, blue, kD, kS, n;
    double fx, fy, fz, c;   /* f = O - C for the camera at O = 0, and c = f.f - r^2 */
} Sphere;

static double read_number(FILE *in) {
    char word[64];
    if (fscanf(in, "%63s", word) != 1) {
        fprintf(stderr, "scalar-tracer: the scene file ends early\n");
        exit(1);
    }
    return strtod(word, NULL);
}

static double clamped_byte(double channel) {
    return 255 * fmax(0, fmin(1, channel));
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: scalar-tracer SCENE.txt IMAGE.ppm\n");
        return 2;
    }
    FILE *in = fopen(argv[1], "r");
    if (in == NULL) {
        perror(argv[1]);
        return 1;
    }
    int width = (int) read_number(in), height = (int) read_number(in), samples = (int) read_number(in);
    double widthM = read_number(in);
    double *sampleX = malloc(sizeof(double) * samples), *sampleY = malloc(sizeof(double) * samples);
    for (int i = 0; i < samples; i++) {
        sampleX[i] = read_number(in);
        sampleY[i] = read_number(in);
    }
    double ambientRed = read_number(in), ambientGreen = read_number(in), ambientBlue = read_number(in);
    int lit = (int) read_number(in);
    double lightX = read_number(in), lightY = read_number(in), lightZ = read_number(in);
    double lightRed = read_number(in), lightGreen = read_number(in), lightBlue = read_number(in);
    double intensity = read_number(in);
    int count = (int) read_number(in);
    Sphere *spheres = malloc(sizeof(Sphere) * (count > 0 ? count : 1));
    for (int i = 0; i < count; i++) {
        Sphere *s = &spheres[i];
        s->cx = read_number(in);
        s->cy = read_number(in);
        s->cz = read_number(in);
        s->radius = read_number(in);
        s->red = read_number(in);
        s->green = read_number(in);
        s->blue = read_number(in);
        s->kD = read_number(in);
        s->kS = read_number(in);
        s->n = read_number(in);
        s->fx = 0 - s->cx;
        s->fy = 0 - s->cy;
        s->fz = 0 - s->cz;
        s->c = (s->fx * s->fx + s->fy * s->fy + s->fz * s->fz) - pow(s->radius, 2);
    }
    fclose(in);

    /* The Camera's image plane. */
    double heightM = widthM / ((double) width / (double) height);
    double xStep = widthM / width, yStep = heightM / height;
    unsigned char *image = malloc((size_t) width * height * 3);
    double scale = 1.0 / samples;

    for (int y = 0; y < height; y++) {
        for (int x = 0; x < width; x++) {
            double sumRed = 0, sumGreen = 0, sumBlue = 0;
            for (int k = 0; k < samples; k++) {
                /* castRay: a unit direction D through the sample's point on the image plane. */
                double px = (xStep - widthM) / 2 + (x + sampleX[k]) * xStep;
                double py = (yStep + heightM) / 2 - (y + sampleY[k]) * yStep;
                double length = sqrt(px * px + py * py + 1 * 1);
                double dx = px / length, dy = py / length, dz = 1 / length;
                double a = dx * dx + dy * dy + dz * dz;

                /* The nearest sphere: the handout's quadratic a s^2 + b s + c = 0, b = 2 D.f. */
                int nearest = -1;
                double best = INFINITY;
                for (int i = 0; i < count; i++) {
                    const Sphere *s = &spheres[i];
                    double b = 2 * (dx * s->fx + dy * s->fy + dz * s->fz);
                    double discriminant = b * b - 4 * a * s->c;
                    if (discriminant < 0) {
                        continue;
                    }
                    double root = sqrt(discriminant);
                    double s1 = (-b - root) / (2 * a), s2 = (-b + root) / (2 * a);
                    double t = s1 > 0 ? s1 : s2;
                    if (t > 0 && t < best) {
                        best = t;
                        nearest = i;
                    }
                }

                double red, green, blue;
                if (nearest < 0) {
                    red = green = blue = 0.1;   /* the background */
                } else {
                    const Sphere *s = &spheres[nearest];
                    /* P = O + s D, N = normalise(P - C). */
                    double X = 0 + best * dx, Y = 0 + best * dy, Z = 0 + best * dz;
                    double nx = X - s->cx, ny = Y - s->cy, nz = Z - s->cz;
                    double nLength = sqrt(nx * nx + ny * ny + nz * nz);
                    nx = nx / nLength;
                    ny = ny / nLength;
                    nz = nz / nLength;
                    red = s->red * ambientRed;
                    green = s->green * ambientGreen;
                    blue = s->blue * ambientBlue;
                    if (lit) {
                        /* I = intensity / (4 pi d^2) times the light's colour; L, V and R = 2 (L.N) N - L. */
                        double lx = lightX - X, ly = lightY - Y, lz = lightZ - Z;
                        double distance = sqrt(lx * lx + ly * ly + lz * lz);
                        double falloff = intensity / (M_PI * 4 * pow(distance, 2));
                        double iRed = falloff * lightRed, iGreen = falloff * lightGreen, iBlue = falloff * lightBlue;
                        lx = lx / distance;
                        ly = ly / distance;
                        lz = lz / distance;
                        double vx = -1 * X, vy = -1 * Y, vz = -1 * Z;
                        double vLength = sqrt(vx * vx + vy * vy + vz * vz);
                        vx = vx / vLength;
                        vy = vy / vLength;
                        vz = vz / vLength;
                        double twiceLdotN = 2 * (lx * nx + ly * ny + lz * nz);
                        double rx = twiceLdotN * nx - lx, ry = twiceLdotN * ny - ly, rz = twiceLdotN * nz - lz;
                        double NdotL = nx * lx + ny * ly + nz * lz;
                        double RdotV = rx * vx + ry * vy + rz * vz;
                        double diffuse = s->kD * fmax(0, NdotL);
                        double specular = s->kS * pow(fmax(0, RdotV), s->n);
                        red = red + diffuse * (s->red * iRed) + specular * (1 * iRed);
                        green = green + diffuse * (s->green * iGreen) + specular * (1 * iGreen);
                        blue = blue + diffuse * (s->blue * iBlue) + specular * (1 * iBlue);
                    }
                }
                sumRed = k == 0 ? red : sumRed + red;
                sumGreen = k == 0 ? green : sumGreen + green;
                sumBlue = k == 0 ? blue : sumBlue + blue;
            }
            unsigned char *pixel = image + ((size_t) y * width + x) * 3;
            pixel[0] = (unsigned char) (int) clamped_byte(scale * sumRed);
            pixel[1] = (unsigned char) (int) clamped_byte(scale * sumGreen);
            pixel[2] = (unsigned char) (int) clamped_byte(scale * sumBlue);
        }
    }

    FILE *out = fopen(argv[2], "wb");
    if (out == NULL) {
        perror(argv[2]);
        return 1;
    }
    fprintf(out, "P6\n%d %d\n255\n", width, height);
    size_t bytes = (size_t) width * height * 3;
    if (fwrite(image, 1, bytes, out) != bytes || fclose(out) != 0) {
        perror(argv[2]);
        return 1;
    }
    return 0;
}
