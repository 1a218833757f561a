package rtd.accel;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Each object's kind as a small number ({@link rtd.geometry.IGeometry#kind}: "sphere",
 * "triangle", ...), for the counts of tests by kind that {@code --stats} prints, and the kinds'
 * names. Numbered by threads that meet the kinds in an order of their own, then anew in the order
 * of each kind's first object in the file ({@link #numberInFileOrder}), so that the counts are
 * the same on every run. Used by {@link HitImageBuilder}.
 */
final class ObjectKinds {

    /** The number of no kind: an object without a box (a plane), which is not listed in tiles. */
    static final byte NONE = -1;
    /** Per object in file order: its kind's number, or {@link #NONE}. */
    private final byte[] kinds;
    private final List<String> names = new ArrayList<>();

    ObjectKinds(int objects) {
        this.kinds = new byte[objects];
    }

    /** Object {@code f} is of kind number {@code kind}, or of {@link #NONE}. */
    void set(int f, byte kind) {
        kinds[f] = kind;
    }

    /** The number of object {@code f}'s kind, or {@link #NONE}. */
    byte of(int f) {
        return kinds[f];
    }

    /** The number of the kind of this name, given it anew if it is the first of its kind; any thread may ask. */
    synchronized byte numberOf(String name) {
        int kind = names.indexOf(name);
        if (kind < 0) {
            kind = names.size();
            names.add(name);
        }
        return (byte) kind;
    }

    /** Numbers the kinds anew in the order of their first objects in the file: a pass over the numbers, not the objects. */
    void numberInFileOrder() {
        int count = names.size();
        byte[] renamed = new byte[count];
        Arrays.fill(renamed, NONE);
        List<String> inOrder = new ArrayList<>();
        for (byte kind : kinds) {
            if (kind != NONE && renamed[kind] == NONE) {
                renamed[kind] = (byte) inOrder.size();
                inOrder.add(names.get(kind));
                if (inOrder.size() == count) {
                    break;
                }
            }
        }
        for (int f = 0; f < kinds.length; f++) {
            if (kinds[f] != NONE) {
                kinds[f] = renamed[kinds[f]];
            }
        }
        names.clear();
        names.addAll(inOrder);
    }

    /** The kinds' names, by number. */
    String[] names() {
        return names.toArray(String[]::new);
    }
}
