!> The mesh operations of med_file: counts, steps, cell types, coordinates, connectivity,
!> names and families, read and written through the MED server (one request each).
submodule (med_file) med_file_mesh
    implicit none

contains
    module procedure med_mesh_count
        type(message_t) :: q, r
        call q%put_int(OP_MESH_COUNT)
        n = exchange(file, q, r, 'count', 'its meshes', st, writing=.false.)
    end procedure med_mesh_count

    module procedure med_mesh_info
        type(message_t) :: q, r
        character(kind=c_char), allocatable :: buffer(:)
        integer(c_int) :: rc, meshdim
        call q%put_int(OP_MESH_INFO)
        call q%put_int(int(it))
        rc = exchange(file, q, r, 'read', 'the description of mesh ' // to_text(it), st, &
                      check=.false.)
        call r%get_chars(buffer)
        name = buffer_text(buffer, 1, MED_NAME_LEN)
        spacedim = r%get_int()
        meshdim = r%get_int()                      ! not used: parasol takes spacedim
        structured = r%get_int() /= 0
        nstep = r%get_int()
        if (st%failed()) return
        if (rc == PLUGIN_BAD_SIZE) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' // &
                to_text(it) // ' has ' // to_text(spacedim) // ' coordinate axes (a mesh ' // &
                'has 1 to 3)')
        else if (rc < 0) then
            call fail(st, file, 'read', 'the description of mesh ' // to_text(it), rc, 0, &
                      writing=.false.)
        end if
    end procedure med_mesh_info

    module procedure med_mesh_step
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_MESH_STEP)
        call q%put_text(mesh)
        call q%put_int(int(it))
        rc = exchange(file, q, r, 'read', 'the computation steps of mesh ' // mesh, st, &
                      writing=.false.)
        numdt = r%get_int()
        numit = r%get_int()
    end procedure med_mesh_step

    module procedure med_count
        type(message_t) :: q, r
        call step_request(q, OP_COUNT, mesh, numdt, numit)
        call q%put_int(int(what))
        call q%put_int(int(geotype))
        n = exchange(file, q, r, 'count', 'the ' // what_text // ' of mesh ' // mesh, st, &
                     writing=.false.)
    end procedure med_count

    module procedure med_cell_type
        type(message_t) :: q, r
        integer(c_int) :: rc
        call step_request(q, OP_CELL_TYPE, mesh, numdt, numit)
        call q%put_int(int(it))
        rc = exchange(file, q, r, 'read', 'the cell types of mesh ' // mesh, st, &
                      writing=.false.)
        geotype = r%get_int()
    end procedure med_cell_type

    module procedure med_read_coordinates
        type(message_t) :: q, r
        real(dp), allocatable :: values(:)
        integer(c_int) :: rc
        coords = 0.0_dp
        call step_request(q, OP_READ_COORDINATES, mesh, numdt, numit)
        call q%put_int(size(coords))
        rc = exchange(file, q, r, 'read', 'the node coordinates of mesh ' // mesh, st, &
                      writing=.false.)
        if (st%failed()) return
        call r%get_reals(values)
        call quiet_signaling_nans(values)
        call take_size(st, file, r, size(values), size(coords))
        if (st%ok()) coords = values
    end procedure med_read_coordinates

    module procedure med_read_connectivity
        type(message_t) :: q, r
        integer(i4), allocatable :: values(:)
        integer(c_int) :: rc
        conn = 0
        call step_request(q, OP_READ_CONNECTIVITY, mesh, numdt, numit)
        call q%put_int(int(geotype))
        call q%put_int(size(conn))
        rc = exchange(file, q, r, 'read', 'the ' // type_name // ' cells of mesh ' // mesh, st, &
                      writing=.false.)
        if (st%failed()) return
        call r%get_ints(values)
        call take_size(st, file, r, size(values), size(conn))
        if (st%ok()) conn = values
    end procedure med_read_connectivity

    module procedure med_read_names
        type(message_t) :: q, r
        character(kind=c_char), allocatable :: buffer(:)
        integer(c_int) :: rc
        integer(i8) :: bytes
        integer(i4) :: k, j
        names = ' '
        bytes = int(MED_SNAME_LEN, i8) * n + 1
        if (bytes > huge(1_c_int)) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': it claims ' &
                // to_text(int(n, i8)) // ' ' // what_text // ' names, more than this ' // &
                'machine can hold')
            return
        end if
        call step_request(q, OP_READ_NAMES, mesh, numdt, numit)
        call q%put_int(int(entity))
        call q%put_int(int(geotype))
        call q%put_int(int(bytes))
        rc = exchange(file, q, r, 'read', 'the names of the ' // what_text // ' of mesh ' // &
                      mesh, st, writing=.false.)
        if (st%failed()) return
        call r%get_chars(buffer)
        call take_size(st, file, r, size(buffer), int(bytes))
        if (st%failed()) return
        do k = 1, min(n, size(names, kind=i4))   ! blank-padded fields of 16 characters
            names(k) = transfer(buffer((k - 1) * MED_SNAME_LEN + 1:k * MED_SNAME_LEN), names(k))
            j = index(names(k), c_null_char)      ! a writer that pads with NULs instead
            if (j > 0) names(k)(j:) = ' '
        end do
    end procedure med_read_names

    module procedure med_read_families
        type(message_t) :: q, r
        integer(i4), allocatable :: values(:)
        integer(c_int) :: rc
        numbers = 0
        call step_request(q, OP_READ_FAMILIES, mesh, numdt, numit)
        call q%put_int(int(entity))
        call q%put_int(int(geotype))
        call q%put_int(size(numbers))
        rc = exchange(file, q, r, 'read', 'the family numbers of the ' // what_text // &
                      ' of mesh ' // mesh, st, writing=.false.)
        if (st%failed()) return
        call r%get_ints(values)
        call take_size(st, file, r, size(values), size(numbers))
        if (st%ok()) numbers = values
    end procedure med_read_families

    module procedure med_family_count
        type(message_t) :: q, r
        call q%put_int(OP_FAMILY_COUNT)
        call q%put_text(mesh)
        n = exchange(file, q, r, 'count', 'the families of mesh ' // mesh, st, writing=.false.)
    end procedure med_family_count

    module procedure med_family_group_count
        type(message_t) :: q, r
        call q%put_int(OP_FAMILY_GROUP_COUNT)
        call q%put_text(mesh)
        call q%put_int(int(it))
        n = exchange(file, q, r, 'read', 'family ' // to_text(it) // ' of mesh ' // mesh, st, &
                     writing=.false.)
    end procedure med_family_group_count

    module procedure med_family_info
        type(message_t) :: q, r
        character(kind=c_char), allocatable :: name_buffer(:), buffer(:)
        integer(c_int) :: rc
        integer(i4) :: k
        groups = ' '
        call q%put_int(OP_FAMILY_INFO)
        call q%put_text(mesh)
        call q%put_int(int(it))
        call q%put_int(size(groups))
        rc = exchange(file, q, r, 'read', 'family ' // to_text(it) // ' of mesh ' // mesh, st, &
                      writing=.false.)
        call r%get_chars(name_buffer)
        name = buffer_text(name_buffer, 1, MED_NAME_LEN)
        number = r%get_int()
        if (st%failed()) return
        call r%get_chars(buffer)
        do k = 1, size(groups, kind=i4)
            groups(k) = buffer_text(buffer, (k - 1) * MED_LNAME_LEN + 1, MED_LNAME_LEN)
        end do
    end procedure med_family_info

    module procedure med_create_mesh
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_CREATE_MESH)
        call q%put_text(mesh)
        call q%put_int(int(spacedim))
        call q%put_text(description)
        rc = exchange(file, q, r, 'create', 'mesh ' // mesh, st, writing=.true.)
    end procedure med_create_mesh

    module procedure med_write_coordinates
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_WRITE_COORDINATES)
        call q%put_text(mesh)
        call q%put_int(size(coords, 2))
        call q%put_reals(reshape(coords, [size(coords)]))
        rc = exchange(file, q, r, 'write', 'the nodes of mesh ' // mesh, st, writing=.true.)
    end procedure med_write_coordinates

    module procedure med_write_connectivity
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_WRITE_CONNECTIVITY)
        call q%put_text(mesh)
        call q%put_int(int(geotype))
        call q%put_int(size(conn, 2))
        call q%put_ints(reshape(conn, [size(conn)]))
        rc = exchange(file, q, r, 'write', 'the cells of mesh ' // mesh, st, writing=.true.)
    end procedure med_write_connectivity

    module procedure med_write_names
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_WRITE_NAMES)
        call q%put_text(mesh)
        call q%put_int(int(entity))
        call q%put_int(int(geotype))
        call q%put_int(size(names))
        call q%put_chars(fixed_chars(names, MED_SNAME_LEN))
        rc = exchange(file, q, r, 'write', 'the entity names of mesh ' // mesh, st, &
                      writing=.true.)
    end procedure med_write_names

    module procedure med_write_families
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_WRITE_FAMILIES)
        call q%put_text(mesh)
        call q%put_int(int(entity))
        call q%put_int(int(geotype))
        call q%put_ints(numbers)
        rc = exchange(file, q, r, 'write', 'the family numbers of mesh ' // mesh, st, &
                      writing=.true.)
    end procedure med_write_families

    module procedure med_create_family
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_CREATE_FAMILY)
        call q%put_text(mesh)
        call q%put_text(name)
        call q%put_int(int(number))
        call q%put_int(size(groups))
        call q%put_chars(fixed_chars(groups, MED_LNAME_LEN))
        rc = exchange(file, q, r, 'write', 'family ' // name // ' of mesh ' // mesh, st, &
                      writing=.true.)
    end procedure med_create_family

    subroutine take_size(st, file, r, got, wanted)
        type(status_t), intent(inout) :: st
        type(med_file_t), intent(in) :: file
        type(message_t), intent(in) :: r
        integer, intent(in) :: got, wanted
        if (r%bad .or. got /= wanted) call set_error(st, STATUS_INTERNAL, 'MED file ' // &
            file%path // ': the MED server sent ' // to_text(int(got, i4)) // ' values for ' &
            // to_text(int(wanted, i4)) // ' (a bug: please report it)')
    end subroutine take_size

    subroutine step_request(q, op, mesh, numdt, numit)
        type(message_t), intent(inout) :: q
        integer, intent(in) :: op
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: numdt, numit
        call q%put_int(op)
        call q%put_text(mesh)
        call q%put_int(int(numdt))
        call q%put_int(int(numit))
    end subroutine step_request

end submodule med_file_mesh
