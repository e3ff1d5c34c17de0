namespace ncpost {}
