package rtd;

import static com.tngtech.archunit.base.DescribedPredicate.not;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.belongToAnyOf;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAPackage;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.accel.Accelerator;

/**
 * The rules of rtd's shape: dependencies point one way, from the command line down to the
 * paper's core, and the book a student reads never reaches into the engine's internals.
 */
@DisplayName("The architecture")
class ArchitectureTest {

    private static final JavaClasses RTD = new ClassFileImporter()
            .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS).importPackages("rtd");

    @Test
    void hasNoCycleAmongItsPackages() {
        slices().matching("rtd.(*)..").should().beFreeOfCycles().check(RTD);
    }

    @Test
    void keepsThePapersCoreFreeOfEverythingBuiltOnIt() {
        noClasses().that().resideInAnyPackage("rtd.math..", "rtd.image..", "rtd.geometry..", "rtd.camera..", "rtd.scene..")
                .should().dependOnClassesThat().resideInAnyPackage("rtd.render..", "rtd.shade..", "rtd.accel..",
                        "rtd.io..", "rtd.cli..", "rtd.explain..", "rtd.view..", "rtd.pov..", "rtd.window..")
                .check(RTD);
    }

    @Test
    void letsTheEngineReadOnlyTheBooksCoreAndTheTracerItPlugsInto() {
        noClasses().that().resideInAPackage("rtd.accel..")
                .should().dependOnClassesThat().resideInAnyPackage("rtd.shade..", "rtd.io..", "rtd.cli..", "rtd.explain..",
                        "rtd.view..", "rtd.pov..", "rtd.window..")
                .check(RTD);
    }

    @Test
    void letsTheBookReachTheEngineOnlyThroughItsOneDoor() {
        noClasses().that().resideOutsideOfPackage("rtd.accel..")
                .should().dependOnClassesThat(resideInAPackage("rtd.accel..").and(not(belongToAnyOf(Accelerator.class))))
                .because("the engine's structures are chosen and built behind Accelerator, and answer through Tracer")
                .check(RTD);
    }

    @Test
    void keepsTheWindowABookPackageThatTheCommandLineBuilds() {
        noClasses().that().resideInAPackage("rtd.window..")
                .should().dependOnClassesThat().resideInAnyPackage("rtd.accel..", "rtd.cli..")
                .check(RTD);
    }
}
