// The bench's white furnace: under a uniform white sky a perfect mirror shows 1, and every raster glossy
// path of a rough mirror or reflector shows the energy the GGX lobe keeps, within the tracer's noise.
#include "accuracy/run/Furnace.hpp"
#include "support/GlTest.hpp"

#include <cstdio>

namespace speculum::test {
namespace {

class BenchFurnace : public GlTest {};

TEST_F(BenchFurnace, PerfectMirrorsKeepEverythingAndRoughOnesTheLobesAlbedo) {
    auto rows = accuracy::runFurnace(renderer());
    ASSERT_TRUE(rows.ok()) << rows.error();
    std::size_t perfect = 0, rough = 0;
    for (const accuracy::FurnaceRow& row : *rows) {
        SCOPED_TRACE(row.surface + " " + row.path + " roughness " + std::to_string(row.roughness) + " view " +
                     std::to_string(row.viewDegrees));
        std::printf("[ measured ] %-13s %-9s r %.2f view %2.0f°: raster %.4f, traced %.4f ± %.4f, E %.4f, "
                    "energy %.4f\n",
                    row.surface.c_str(), row.path.c_str(), row.roughness, row.viewDegrees, row.raster,
                    row.traced, row.tracedError, row.albedo, row.energy());
        if (row.roughness == 0.0) {
            ++perfect;
            EXPECT_NEAR(row.traced, 1.0, 1e-3) << "the tracer's perfect mirror";
            EXPECT_NEAR(row.energy(), 1.0, 5e-3) << "the raster's perfect mirror (half-float buffers)";
            continue;
        }
        ++rough;
        // The tracer integrates the lobe: its value is E within its own noise.
        EXPECT_NEAR(row.traced, row.albedo, 4.0 * row.tracedError + 1e-3);
        // The raster path keeps the same energy: within the tracer's noise, the albedo table's reading
        // between its nodes, and (on the ball) the tessellated normal.
        const double slack = row.surface == "reflector" ? 1.5e-2 : 6e-3;
        EXPECT_NEAR(row.raster, row.traced, 4.0 * row.tracedError + slack);
        // And so the energy figure the report gives: E itself, to the table's reading and the buffer.
        EXPECT_NEAR(row.energy(), 1.0, row.surface == "reflector" ? 1.5e-2 : 1e-2);
    }
    EXPECT_EQ(perfect, 3u) << "the floor at two views and the ball";
    EXPECT_EQ(rough, 5u * 3u * 3u) << "five roughnesses, three surfaces, three raster paths";
}

} // namespace
} // namespace speculum::test
