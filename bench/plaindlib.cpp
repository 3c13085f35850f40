// toonface-bench-plaindlib MODEL IMAGE: dlib's own face detector and 68-point predictor on one
// photo and nothing else, the yardstick beside which bench_startup.cpp times toonface-cli's
// whole process. Prints the number of faces and the first face's first point.

#include <dlib/image_io.h>
#include <dlib/image_processing.h>
#include <dlib/image_processing/frontal_face_detector.h>

#include <cstdio>

int main(int argc, char *argv[])
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: toonface-bench-plaindlib MODEL IMAGE\n");
        return 2;
    }
    try {
        dlib::frontal_face_detector detector = dlib::get_frontal_face_detector();
        dlib::shape_predictor predictor;
        dlib::deserialize(argv[1]) >> predictor;
        dlib::array2d<unsigned char> image;
        dlib::load_image(image, argv[2]);
        const std::vector<dlib::rectangle> faces = detector(image);
        if (faces.empty()) {
            std::printf("0\n");
            return 4;
        }
        const dlib::full_object_detection shape = predictor(image, faces[0]);
        std::printf("%zu %ld %ld\n", faces.size(), shape.part(0).x(), shape.part(0).y());
    } catch (const std::exception &e) {
        std::fprintf(stderr, "toonface-bench-plaindlib: %s\n", e.what());
        return 1;
    }
    return 0;
}
