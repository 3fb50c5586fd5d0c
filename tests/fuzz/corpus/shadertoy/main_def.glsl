int main = 1;
void  main  (){}
void mainImage(