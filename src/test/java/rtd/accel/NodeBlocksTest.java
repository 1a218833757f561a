package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

@DisplayName("The blocks of a tree being built")
class NodeBlocksTest {

    @Test
    void handOverEveryNodeAtItsNumberWhenTheTreeOutgrowsTheFirstBlock() {
        NodeBlocks tree = new NodeBlocks(200); // blocks of 100 nodes
        NodeBlocks.Run first = tree.newRun();
        NodeBlocks.Run second = tree.newRun();
        int inner = 0;
        for (int k = 0; k < 150; k++) { // both runs take numbers, up to the third block
            int child = (k % 2 == 0 ? first : second).pair();
            tree.setInner(inner, child);
            tree.setBox(inner, new float[] {inner, 1, 2, 3, 4, 5});
            inner = child;
        }
        tree.setLeaf(inner, 7, 3);
        tree.setBox(inner, new float[] {inner, 1, 2, 3, 4, 5});

        float[] bounds = tree.bounds();
        int[] nodes = tree.nodes();

        int node = 0;
        for (int depth = 0; depth < 150; depth++) {
            assertThat(nodes[2 * node + 1]).isEqualTo(Bvh.INNER);
            assertThat(bounds[6 * node]).isEqualTo(node);
            node = nodes[2 * node];
        }
        assertThat(node).isGreaterThan(200);
        assertThat(nodes[2 * node]).isEqualTo(7);
        assertThat(nodes[2 * node + 1]).isEqualTo(3);
        assertThat(bounds[6 * node + 5]).isEqualTo(5);
    }

    @Test
    void handOverTheFirstBlockItselfWhenTheTreeFitsInIt() {
        NodeBlocks tree = new NodeBlocks(1000);
        int child = tree.newRun().pair();
        tree.setInner(0, child);
        tree.setLeaf(child, 0, 1);
        tree.setLeaf(child + 1, 1, 1);

        int[] nodes = tree.nodes();

        assertThat(nodes).hasSize(2 * 500);
        assertThat(nodes[0]).isEqualTo(child);
        assertThat(nodes[2 * child + 3]).isEqualTo(1);
    }
}
