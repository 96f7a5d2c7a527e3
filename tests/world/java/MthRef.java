// Reference for the float/double math in emulator/world, run on a real JVM so that Java's own
// float arithmetic, casts and Math.sin/asin/cos produce the expected values.
// The formulas restate net.minecraft.util.Mth, Vec3, LocalCoordinates, CommandSourceStack.facing
// and ExecuteCommand's store casts (decompiled 1.21). Input: one query per line, numbers as raw
// IEEE bits in hex; output: one line per query, results as raw bits in hex (ints in decimal).
import java.io.BufferedReader;
import java.io.InputStreamReader;

public class MthRef {
    static final float[] SIN = new float[65536];
    static final double[] ASIN_TAB = new double[257];
    static final double[] COS_TAB = new double[257];
    static final double FRAC_BIAS = Double.longBitsToDouble(4805340802404319232L);

    static {
        for (int i = 0; i < SIN.length; i++) {
            SIN[i] = (float) Math.sin((double) i * Math.PI * 2.0 / 65536.0);
        }
        for (int i = 0; i < 257; i++) {
            double a = Math.asin((double) i / 256.0);
            COS_TAB[i] = Math.cos(a);
            ASIN_TAB[i] = a;
        }
    }

    static float sin(float x) { return SIN[(int) (x * 10430.378F) & 65535]; }
    static float cos(float x) { return SIN[(int) (x * 10430.378F + 16384.0F) & 65535]; }

    static float wrap(float v) {
        float f = v % 360.0F;
        if (f >= 180.0F) f -= 360.0F;
        if (f < -180.0F) f += 360.0F;
        return f;
    }

    static double fastInvSqrt(double x) {
        double half = 0.5 * x;
        long bits = 6910469410427058090L - (Double.doubleToRawLongBits(x) >> 1);
        double y = Double.longBitsToDouble(bits);
        return y * (1.5 - half * y * y);
    }

    static double atan2(double y, double x) {
        double sq = x * x + y * y;
        if (Double.isNaN(sq)) return Double.NaN;
        boolean ny = y < 0.0;
        if (ny) y = -y;
        boolean nx = x < 0.0;
        if (nx) x = -x;
        boolean steep = y > x;
        if (steep) { double t = x; x = y; y = t; }
        double inv = fastInvSqrt(sq);
        x *= inv;
        y *= inv;
        double biased = FRAC_BIAS + y;
        int i = (int) Double.doubleToRawLongBits(biased);
        double c = y * COS_TAB[i] - x * (biased - FRAC_BIAS);
        double a = ASIN_TAB[i] + (6.0 + c * c) * c * 0.16666666666666666;
        if (steep) a = (Math.PI / 2) - a;
        if (nx) a = Math.PI - a;
        if (ny) a = -a;
        return a;
    }

    static int floor(double d) { int i = (int) d; return d < (double) i ? i - 1 : i; }
    static int floorf(float f) { int i = (int) f; return f < (float) i ? i - 1 : i; }

    static float f(String s) { return Float.intBitsToFloat(Integer.parseUnsignedInt(s, 16)); }
    static double d(String s) { return Double.longBitsToDouble(Long.parseUnsignedLong(s, 16)); }
    static String hf(float v) { return Integer.toHexString(Float.floatToRawIntBits(v)); }
    static String hd(double v) { return Long.toHexString(Double.doubleToRawLongBits(v)); }

    static String answer(String[] a) {
        switch (a[0]) {
            case "sin": return hf(sin(f(a[1])));
            case "cos": return hf(cos(f(a[1])));
            case "wrap": return hf(wrap(f(a[1])));
            case "atan2": return hd(atan2(d(a[1]), d(a[2])));
            case "facing":
            case "facing117": {
                // 1.17 and older: double d3 = (double) Mth.sqrt(...), a float square root.
                double dx = d(a[4]) - d(a[1]), dy = d(a[5]) - d(a[2]), dz = d(a[6]) - d(a[3]);
                double h = a[0].equals("facing") ? Math.sqrt(dx * dx + dz * dz) : (double) (float) Math.sqrt(dx * dx + dz * dz);
                float pitch = wrap((float) (-(atan2(dy, h) * (double) (180.0F / (float) Math.PI))));
                float yaw = wrap((float) (atan2(dz, dx) * (double) (180.0F / (float) Math.PI)) - 90.0F);
                return hf(yaw) + " " + hf(pitch);
            }
            case "local": {
                double ox = d(a[1]), oy = d(a[2]), oz = d(a[3]);
                float yaw = f(a[4]), pitch = f(a[5]);
                double left = d(a[6]), up = d(a[7]), fwd = d(a[8]);
                float c1 = cos((yaw + 90.0F) * (float) (Math.PI / 180.0));
                float s1 = sin((yaw + 90.0F) * (float) (Math.PI / 180.0));
                float c2 = cos(-pitch * (float) (Math.PI / 180.0));
                float s2 = sin(-pitch * (float) (Math.PI / 180.0));
                float c3 = cos((-pitch + 90.0F) * (float) (Math.PI / 180.0));
                float s3 = sin((-pitch + 90.0F) * (float) (Math.PI / 180.0));
                double[] fw = {(double) (c1 * c2), (double) s2, (double) (s1 * c2)};
                double[] u = {(double) (c1 * c3), (double) s3, (double) (s1 * c3)};
                double[] l = {
                    (fw[1] * u[2] - fw[2] * u[1]) * -1.0,
                    (fw[2] * u[0] - fw[0] * u[2]) * -1.0,
                    (fw[0] * u[1] - fw[1] * u[0]) * -1.0};
                return hd(ox + (fw[0] * fwd + u[0] * up + l[0] * left)) + " "
                    + hd(oy + (fw[1] * fwd + u[1] * up + l[1] * left)) + " "
                    + hd(oz + (fw[2] * fwd + u[2] * up + l[2] * left));
            }
            case "dir": {
                float yaw = f(a[1]), pitch = f(a[2]);
                float cy = cos(-yaw * 0.017453292F - 3.1415927F);
                float sy = sin(-yaw * 0.017453292F - 3.1415927F);
                float cp = -cos(-pitch * 0.017453292F);
                float sp = sin(-pitch * 0.017453292F);
                return hd((double) (sy * cp)) + " " + hd((double) sp) + " " + hd((double) (cy * cp));
            }
            case "store": {
                double v = (double) Integer.parseInt(a[1]) * d(a[2]);
                return (int) v + " " + (long) v + " " + (short) (int) v + " " + (byte) (int) v + " " + hf((float) v);
            }
            case "view": {
                float yaw = f(a[1]), pitch = f(a[2]);
                float p = pitch * (float) (Math.PI / 180.0), y = -yaw * (float) (Math.PI / 180.0);
                float cy = cos(y), sy = sin(y), cp = cos(p), sp = sin(p);
                return hd((double) (sy * cp)) + " " + hd((double) (-sp)) + " " + hd((double) (cy * cp));
            }
            case "narrow": {
                // DoubleTag and FloatTag getAsByte/getAsShort/getAsInt/getAsLong.
                double v = d(a[1]);
                float w = (float) v;
                return (byte) (floor(v) & 255) + " " + (short) (floor(v) & 65535) + " " + floor(v) + " "
                    + (long) Math.floor(v) + " " + (byte) (floorf(w) & 255) + " " + (short) (floorf(w) & 65535)
                    + " " + floorf(w) + " " + (long) w;
            }
            case "dtext": return Double.toString(d(a[1]));
            case "ftext": return Float.toString(f(a[1]));
            case "tables": {
                StringBuilder rows = new StringBuilder();
                for (int i = 0; i < 257; i++) {
                    rows.append(i == 0 ? "" : "\n").append(hd(ASIN_TAB[i])).append(' ').append(hd(COS_TAB[i]));
                }
                return rows.toString();
            }
            default: return "?";
        }
    }

    public static void main(String[] args) throws Exception {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in));
        StringBuilder out = new StringBuilder();
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            out.append(answer(line.trim().split(" "))).append('\n');
        }
        System.out.print(out);
    }
}
