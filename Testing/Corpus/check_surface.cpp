// Independent check of one corpus surface (an OFF of triangles written by
// surface_tool.py): closed, edge-manifold, vertex-manifold, consistently
// oriented, not self-intersecting (CGAL exact predicates), enclosed volume.
// Prints one JSON object on stdout. Built by fetch.sh with g++ against
// Debian's header-only CGAL; the plugin's code is not used, so the corpus
// check does not trust what it is meant to test.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: check_surface FILE.off\n";
        return 2;
    }
    std::ifstream in(argv[1]);
    std::string header;
    std::size_t nv = 0, nf = 0, ne = 0;
    in >> header >> nv >> nf >> ne;
    if (!in || header != "OFF") {
        std::cerr << "not an OFF file: " << argv[1] << "\n";
        return 2;
    }
    std::vector<Point> points(nv);
    for (auto& p : points) {
        double x, y, z;
        in >> x >> y >> z;
        p = Point(x, y, z);
    }
    std::vector<std::array<std::size_t, 3>> tris(nf);
    for (auto& t : tris) {
        int n = 0;
        in >> n >> t[0] >> t[1] >> t[2];
        if (n != 3) {
            std::cerr << "not a triangle\n";
            return 2;
        }
    }
    if (!in) {
        std::cerr << "truncated OFF file\n";
        return 2;
    }
    // undirected edge -> uses; directed edge -> uses
    std::map<std::pair<std::size_t, std::size_t>, int> undirected, directed;
    for (const auto& t : tris)
        for (int k = 0; k < 3; ++k) {
            std::size_t a = t[k], b = t[(k + 1) % 3];
            ++directed[{ a, b }];
            ++undirected[{ std::min(a, b), std::max(a, b) }];
        }
    std::size_t boundary = 0, nonmanifold = 0, misoriented = 0;
    for (const auto& e : undirected) {
        if (e.second == 1) ++boundary;
        if (e.second > 2) ++nonmanifold;
    }
    for (const auto& e : directed)
        if (e.second > 1) ++misoriented;
    std::vector<std::vector<std::size_t>> polygons;
    for (const auto& t : tris) polygons.push_back({ t[0], t[1], t[2] });
    bool polygonMesh = PMP::is_polygon_soup_a_polygon_mesh(polygons);
    long long intersections = -1;
    double volume = 0.0;
    for (const auto& t : tris) {
        const Point &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
        volume += (a.x() * (b.y() * c.z() - b.z() * c.y()) - a.y() * (b.x() * c.z() - b.z() * c.x())
                      + a.z() * (b.x() * c.y() - b.y() * c.x())) / 6.0;
    }
    if (polygonMesh) {
        Mesh mesh;
        PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
        std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
        PMP::self_intersections(mesh, std::back_inserter(pairs));
        intersections = static_cast<long long>(pairs.size());
    }
    std::printf("{\"vertices\": %zu, \"triangles\": %zu, \"boundary_edges\": %zu, \"nonmanifold_edges\": %zu, "
                "\"misoriented_edges\": %zu, \"polygon_mesh\": %s, \"self_intersecting_pairs\": %lld, "
                "\"volume\": %.17g}\n",
        nv, nf, boundary, nonmanifold, misoriented, polygonMesh ? "true" : "false", intersections, volume);
    return 0;
}
