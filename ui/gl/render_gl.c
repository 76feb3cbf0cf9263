/* SPDX-License-Identifier: MIT */
/*
 * Small GL helpers for the whole renderer: shader programs, what the context offers, its
 * error flags. Below the frame (render.c) and its layers (render_*.c): it knows nothing of
 * struct render or the app.
 */
#include "render_gl.h"

#include <stdio.h>
#include <string.h>

static GLuint compile(const char *name, GLenum type, const char *src)
{
	GLuint shader = glCreateShader(type);
	GLint ok = GL_FALSE;

	if (!shader)
		return 0;
	glShaderSource(shader, 1, &src, NULL);
	glCompileShader(shader);
	glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
	if (!ok) {
		char log[1024] = "";

		glGetShaderInfoLog(shader, sizeof(log), NULL, log);
		fprintf(stderr, "render: %s %s shader does not compile: %s\n", name,
			type == GL_VERTEX_SHADER ? "vertex" : "fragment", log);
		glDeleteShader(shader);
		return 0;
	}
	return shader;
}

GLuint render_program(const char *name, const char *vertex_src, const char *fragment_src,
		      const char *const *attribs, const GLuint *locations, size_t nattribs)
{
	GLuint vs, fs, program;
	GLint ok = GL_FALSE;

	vs = compile(name, GL_VERTEX_SHADER, vertex_src);
	fs = vs ? compile(name, GL_FRAGMENT_SHADER, fragment_src) : 0;
	program = fs ? glCreateProgram() : 0;
	if (program) {
		glAttachShader(program, vs);
		glAttachShader(program, fs);
		for (size_t i = 0; i < nattribs; i++)
			glBindAttribLocation(program, locations[i], attribs[i]);
		glLinkProgram(program);
		glGetProgramiv(program, GL_LINK_STATUS, &ok);
		if (!ok) {
			char log[1024] = "";

			glGetProgramInfoLog(program, sizeof(log), NULL, log);
			fprintf(stderr, "render: %s program does not link: %s\n", name, log);
			glDeleteProgram(program);
			program = 0;
		}
	}
	/* the program keeps what it needs */
	glDeleteShader(vs);
	glDeleteShader(fs);
	return program;
}

bool render_program_tree_init(struct render_program_tree *p, const char *name, const char *vs,
			      const char *fs, const char *const *attribs, const GLuint *locations,
			      size_t nattribs)
{
	p->program = render_program(name, vs, fs, attribs, locations, nattribs);
	if (!p->program)
		return false;
	p->mvp = glGetUniformLocation(p->program, "u_mvp");
	p->color = glGetUniformLocation(p->program, "u_color");
	p->light = glGetUniformLocation(p->program, "u_light");
	p->two_sided = glGetUniformLocation(p->program, "u_two_sided");
	return true;
}

bool render_has_extension(const char *name)
{
	const char *list = (const char *)glGetString(GL_EXTENSIONS);
	size_t n = strlen(name);

	for (const char *p = list; p && (p = strstr(p, name)); p += n) {
		if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
			return true;
	}
	return false;
}

/* From "OpenGL ES 3.2 Mesa ...": 3. */
int render_gl_major_version(void)
{
	const char *version = (const char *)glGetString(GL_VERSION);
	int major = 0, minor = 0;

	if (!version || sscanf(version, "OpenGL ES %d.%d", &major, &minor) != 2)
		return 2;
	return major;
}

void render_drain_gl_errors(void)
{
	/* bounded: a lost context may report errors forever */
	for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; i++)
		;
}

void render_mat4_mul(const float a[16], const float b[16], float out[16])
{
	for (int col = 0; col < 4; col++)
		for (int row = 0; row < 4; row++) {
			float v = 0.0f;

			for (int k = 0; k < 4; k++)
				v += a[k * 4 + row] * b[col * 4 + k];
			out[col * 4 + row] = v;
		}
}
