!> The run's heap of mutable containers: the lists and dicts of the deck language
!> (doc/deck-language.md, "Values"). As in Python, a list or a dict is one object that every
!> name, tuple, list or dict holding it shares: a deck value VK_LIST/VK_DICT refers to its
!> container by number (value_t%i), so `L.append(x)` is seen through every reference, in
!> O(1) amortised time (capacity doubles). Dicts keep their insertion order and find a key
!> through an open-addressing hash table of Python's key equality (1 == 1.0 == True).
!>
!> Containers that nothing refers to any more are collected (mark and sweep) at points the
!> interpreter chooses, where every live reference is reachable from its roots: `mark` each
!> root value, then `sweep`. Values handed to commands and concept methods are flat copies
!> (`flatten`), and values coming back are made containers again (`adopt`).
module deck_heap
    use kinds, only: dp, i8
    use strings, only: string_t
    use deck_value
    implicit none
    private

    !> Items of all live containers together: a bound on the heap's memory (about 130
    !> bytes an item), far beyond what decks build (lists of node names, of loads).
    integer(i8), parameter, public :: MAX_LIVE_ITEMS = 4000000_i8

    !> One list or dict. kind 0: a free slot. A dict's keys(k) maps to items(k); table(:)
    !> holds key indices (0 = empty slot), its size a power of two at least 2 n.
    type :: container_t
        integer :: kind = 0
        integer :: n = 0
        type(value_t), allocatable :: items(:)
        type(value_t), allocatable :: keys(:)
        integer, allocatable :: table(:)
        logical :: marked = .false.
    end type container_t

    type, public :: heap_t
        type(container_t), allocatable :: boxes(:)
        integer :: nbox = 0                       !< slots used (live or free)
        integer, allocatable :: free(:)
        integer :: nfree = 0
        integer(i8) :: live_items = 0             !< items of the live containers
        integer(i8) :: items_at_last_sweep = 0
        integer, allocatable, private :: stack(:) !< marking work list
        integer, private :: nstack = 0
    contains
        procedure :: reset => heap_reset
        procedure :: new_list => heap_new_list
        procedure :: new_dict => heap_new_dict
        procedure :: kind_of => heap_kind_of
        procedure :: length => heap_length
        procedure :: get => heap_get
        procedure :: set => heap_set
        procedure :: append => heap_append
        procedure :: insert => heap_insert
        procedure :: remove_at => heap_remove_at
        procedure :: items_of => heap_items_of
        procedure :: set_items => heap_set_items
        procedure :: key_at => heap_key_at
        procedure :: dict_find => heap_dict_find
        procedure :: dict_set => heap_dict_set
        procedure :: dict_delete => heap_dict_delete
        procedure :: keys_of => heap_keys_of
        procedure :: clear => heap_clear
        procedure :: mark => heap_mark
        procedure :: sweep => heap_sweep
        procedure :: over_limit => heap_over_limit
        procedure :: flatten
        procedure :: adopt
    end type heap_t

    !> Containers nested deeper than this cannot be handed to a command (a list that holds
    !> itself would be endless).
    integer, parameter, public :: MAX_FLAT_DEPTH = 100

    public :: hashable, keys_equal

contains

    !> Frees every container (between the check and the run pass).
    subroutine heap_reset(self)
        class(heap_t), intent(inout) :: self
        if (allocated(self%boxes)) deallocate (self%boxes)
        if (allocated(self%free)) deallocate (self%free)
        if (allocated(self%stack)) deallocate (self%stack)
        allocate (self%boxes(64), self%free(64), self%stack(64))
        self%nbox = 0; self%nfree = 0; self%nstack = 0
        self%live_items = 0; self%items_at_last_sweep = 0
    end subroutine heap_reset

    !> A new container of kind VK_LIST or VK_DICT; its number.
    integer function new_box(self, kind) result(id)
        class(heap_t), intent(inout) :: self
        integer, intent(in) :: kind
        type(container_t), allocatable :: bigger(:)
        integer :: k
        if (.not. allocated(self%boxes)) call self%reset()
        if (self%nfree > 0) then
            id = self%free(self%nfree)
            self%nfree = self%nfree - 1
        else
            if (self%nbox == size(self%boxes)) then
                allocate (bigger(2 * size(self%boxes)))
                do k = 1, self%nbox
                    call move_box(self%boxes(k), bigger(k))
                end do
                call move_alloc(bigger, self%boxes)
            end if
            self%nbox = self%nbox + 1
            id = self%nbox
        end if
        self%boxes(id)%kind = kind
        self%boxes(id)%n = 0
        self%boxes(id)%marked = .false.
        allocate (self%boxes(id)%items(4))
        if (kind == VK_DICT) then
            allocate (self%boxes(id)%keys(4), self%boxes(id)%table(8))
            self%boxes(id)%table = 0
        end if
    end function new_box

    subroutine move_box(from, to)
        type(container_t), intent(inout) :: from
        type(container_t), intent(inout) :: to
        to%kind = from%kind; to%n = from%n; to%marked = from%marked
        if (allocated(from%items)) call move_alloc(from%items, to%items)
        if (allocated(from%keys)) call move_alloc(from%keys, to%keys)
        if (allocated(from%table)) call move_alloc(from%table, to%table)
    end subroutine move_box

    !> Moves value `from` into `to` without copying its strings and trees.
    subroutine move_value(from, to)
        type(value_t), intent(inout) :: from
        type(value_t), intent(inout) :: to
        to%kind = from%kind; to%i = from%i; to%r = from%r
        to%line = from%line; to%col = from%col
        to%obj => from%obj
        if (allocated(to%s)) deallocate (to%s)
        if (allocated(from%s)) call move_alloc(from%s, to%s)
        if (allocated(to%tree)) deallocate (to%tree)
        if (allocated(from%tree)) call move_alloc(from%tree, to%tree)
    end subroutine move_value

    !> Makes room for n items in box b (capacity doubles).
    subroutine reserve(box, n)
        type(container_t), intent(inout) :: box
        integer, intent(in) :: n
        type(value_t), allocatable :: bigger(:)
        integer :: k, cap
        if (n <= size(box%items)) return
        cap = max(2 * size(box%items), n)
        allocate (bigger(cap))
        do k = 1, box%n
            call move_value(box%items(k), bigger(k))
        end do
        call move_alloc(bigger, box%items)
        if (box%kind == VK_DICT) then
            allocate (bigger(cap))
            do k = 1, box%n
                call move_value(box%keys(k), bigger(k))
            end do
            call move_alloc(bigger, box%keys)
        end if
    end subroutine reserve

    !> A new list holding items; its value (VK_LIST).
    function heap_new_list(self, items) result(v)
        class(heap_t), intent(inout) :: self
        type(value_t), intent(in) :: items(:)
        type(value_t) :: v
        integer :: id, k
        id = new_box(self, VK_LIST)
        call reserve(self%boxes(id), size(items))
        do k = 1, size(items)
            self%boxes(id)%items(k) = items(k)
        end do
        self%boxes(id)%n = size(items)
        self%live_items = self%live_items + size(items)
        v%kind = VK_LIST
        v%i = id
    end function heap_new_list

    !> A new empty dict; its value (VK_DICT).
    function heap_new_dict(self) result(v)
        class(heap_t), intent(inout) :: self
        type(value_t) :: v
        v%kind = VK_DICT
        v%i = new_box(self, VK_DICT)
    end function heap_new_dict

    !> VK_LIST or VK_DICT for a live container, 0 otherwise.
    pure integer function heap_kind_of(self, id)
        class(heap_t), intent(in) :: self
        integer(i8), intent(in) :: id
        heap_kind_of = 0
        if (id < 1 .or. id > self%nbox) return
        heap_kind_of = self%boxes(id)%kind
    end function heap_kind_of

    !> Number of items (list) or keys (dict).
    pure integer function heap_length(self, id)
        class(heap_t), intent(in) :: self
        integer(i8), intent(in) :: id
        heap_length = self%boxes(id)%n
    end function heap_length

    !> Item k (1-based) of a list, or the value of the k-th key of a dict.
    function heap_get(self, id, k) result(v)
        class(heap_t), intent(in) :: self
        integer(i8), intent(in) :: id
        integer, intent(in) :: k
        type(value_t) :: v
        v = self%boxes(id)%items(k)
    end function heap_get

    !> The k-th key (1-based, insertion order) of a dict.
    function heap_key_at(self, id, k) result(v)
        class(heap_t), intent(in) :: self
        integer(i8), intent(in) :: id
        integer, intent(in) :: k
        type(value_t) :: v
        v = self%boxes(id)%keys(k)
    end function heap_key_at

    !> Replaces item k (1-based) of a list.
    subroutine heap_set(self, id, k, v)
        class(heap_t), intent(inout) :: self
        integer(i8), intent(in) :: id
        integer, intent(in) :: k
        type(value_t), intent(in) :: v
        self%boxes(id)%items(k) = v
    end subroutine heap_set

    !> Appends v to a list (O(1) amortised).
    subroutine heap_append(self, id, v)
        class(heap_t), intent(inout) :: self
        integer(i8), intent(in) :: id
        type(value_t), intent(in) :: v
        type(value_t) :: copy
        copy = v                                  ! v may be an item of this very list
        associate (box => self%boxes(id))
            call reserve(box, box%n + 1)
            box%n = box%n + 1
            call move_value(copy, box%items(box%n))
        end associate
        self%live_items = self%live_items + 1
    end subroutine heap_append

    !> Inserts v before item k (1-based; k = n + 1 appends).
    subroutine heap_insert(self, id, k, v)
        class(heap_t), intent(inout) :: self
        integer(i8), intent(in) :: id
        integer, intent(in) :: k
        type(value_t), intent(in) :: v
        type(value_t) :: copy
        integer :: j
        copy = v
        associate (box => self%boxes(id))
            call reserve(box, box%n + 1)
            do j = box%n, k, -1
                call move_value(box%items(j), box%items(j + 1))
            end do
            box%n = box%n + 1
            call move_value(copy, box%items(k))
        end associate
        self%live_items = self%live_items + 1
    end subroutine heap_insert

    !> Removes item k (1-based) of a list.
    subroutine heap_remove_at(self, id, k)
        class(heap_t), intent(inout) :: self
        integer(i8), intent(in) :: id
        integer, intent(in) :: k
        integer :: j
        associate (box => self%boxes(id))
            do j = k, box%n - 1
                call move_value(box%items(j + 1), box%items(j))
            end do
            box%items(box%n) = value_t()
            box%n = box%n - 1
        end associate
        self%live_items = self%live_items - 1
    end subroutine heap_remove_at

    !> Empties a list or a dict.
    subroutine heap_clear(self, id)
        class(heap_t), intent(inout) :: self
        integer(i8), intent(in) :: id
        associate (box => self%boxes(id))
            self%live_items = self%live_items - box%n
            if (box%kind == VK_DICT) self%live_items = self%live_items - box%n
            deallocate (box%items)
            allocate (box%items(4))
            if (box%kind == VK_DICT) then
                deallocate (box%keys, box%table)
                allocate (box%keys(4), box%table(8))
                box%table = 0
            end if
            box%n = 0
        end associate
    end subroutine heap_clear

    !> The items of a list (the values of a dict), a copy.
    function heap_items_of(self, id) result(items)
        class(heap_t), intent(in) :: self
        integer(i8), intent(in) :: id
        type(value_t), allocatable :: items(:)
        items = self%boxes(id)%items(1:self%boxes(id)%n)
    end function heap_items_of

    !> The keys of a dict in insertion order, a copy.
    function heap_keys_of(self, id) result(keys)
        class(heap_t), intent(in) :: self
        integer(i8), intent(in) :: id
        type(value_t), allocatable :: keys(:)
        keys = self%boxes(id)%keys(1:self%boxes(id)%n)
    end function heap_keys_of

    !> Replaces every item of a list (L[:] = ..., L.sort(), L.reverse()).
    subroutine heap_set_items(self, id, items)
        class(heap_t), intent(inout) :: self
        integer(i8), intent(in) :: id
        type(value_t), intent(in) :: items(:)
        type(value_t), allocatable :: copy(:)
        integer :: k
        copy = items
        associate (box => self%boxes(id))
            self%live_items = self%live_items - box%n + size(copy)
            deallocate (box%items)
            allocate (box%items(max(4, size(copy))))
            do k = 1, size(copy)
                call move_value(copy(k), box%items(k))
            end do
            box%n = size(copy)
        end associate
    end subroutine heap_set_items

    ! ---- dicts ------------------------------------------------------------------------------

    !> True when v can be a dict key (Python's hashable values: numbers, strings, None,
    !> concepts, and tuples of them).
    pure logical function hashable(v)
        type(value_t), intent(in) :: v
        select case (v%kind)
        case (VK_INT, VK_REAL, VK_BOOL, VK_STR, VK_NONE, VK_CONCEPT, VK_DEF, VK_BUILTIN)
            hashable = .true.
        case (VK_TUPLE)
            hashable = .true.
            if (allocated(v%tree)) hashable = .not. any(v%tree%kind == VK_LIST .or. &
                v%tree%kind == VK_DICT .or. v%tree%kind == VK_FACTOR)
        case default
            hashable = .false.
        end select
    end function hashable

    !> Python's equality of two hashable keys: numbers by value (1 == 1.0 == True), strings
    !> by text, concepts by identity, tuples item by item.
    recursive logical function keys_equal(a, b) result(same)
        type(value_t), intent(in) :: a, b
        integer :: k, n
        same = .false.
        if (is_number(a) .and. is_number(b)) then
            if (a%kind /= VK_REAL .and. b%kind /= VK_REAL) then
                same = a%i == b%i
            else
                same = as_real(a) >= as_real(b) .and. as_real(a) <= as_real(b)
            end if
            return
        end if
        if (a%kind /= b%kind) return
        select case (a%kind)
        case (VK_STR)
            same = a%s == b%s .and. len(a%s) == len(b%s)
        case (VK_NONE)
            same = .true.
        case (VK_CONCEPT)
            same = associated(a%obj, b%obj)
        case (VK_DEF)
            same = a%i == b%i
        case (VK_BUILTIN)
            same = a%s == b%s
        case (VK_TUPLE)
            n = nitems(a)
            if (n /= nitems(b)) return
            do k = 1, n
                if (.not. keys_equal(item(a, k), item(b, k))) return
            end do
            same = .true.
        end select
    end function keys_equal

    !> A hash of a hashable key consistent with keys_equal.
    recursive integer(i8) function key_hash(v) result(h)
        type(value_t), intent(in) :: v
        integer :: k
        integer(i8), parameter :: PRIME = 1099511628211_i8
        real(dp) :: x
        h = 0
        select case (v%kind)
        case (VK_INT, VK_BOOL)
            h = v%i
        case (VK_REAL)
            x = v%r
            if (abs(x) < 9.0e18_dp) then
                if (x >= aint(x) .and. x <= aint(x)) then
                    h = int(x, i8)                 ! 2.0 hashes as 2
                    return
                end if
            end if
            h = transfer(x, h)
        case (VK_STR)
            h = -3750763034362895579_i8
            do k = 1, len(v%s)
                h = ieor(h, int(iachar(v%s(k:k)), i8))
                h = h * PRIME
            end do
        case (VK_NONE)
            h = 7
        case (VK_CONCEPT)
            h = 11
            if (associated(v%obj)) then
                if (allocated(v%obj%name)) h = key_hash(str_value(v%obj%name))
            end if
        case (VK_DEF)
            h = v%i * 31
        case (VK_BUILTIN)
            h = key_hash(str_value(v%s)) + 13
        case (VK_TUPLE)
            h = 17
            do k = 1, nitems(v)
                h = h * 1000003_i8 + key_hash(item(v, k))
            end do
        end select
    end function key_hash

    !> The table slot of key `key` in dict box: where it is, or the empty slot where it
    !> would go.
    integer function probe(box, key) result(slot)
        type(container_t), intent(in) :: box
        type(value_t), intent(in) :: key
        integer :: mask
        mask = size(box%table) - 1
        slot = int(iand(key_hash(key), int(mask, i8))) + 1
        do
            if (box%table(slot) == 0) return
            if (keys_equal(box%keys(box%table(slot)), key)) return
            slot = iand(slot, mask) + 1
        end do
    end function probe

    subroutine rebuild_table(box, size_wanted)
        type(container_t), intent(inout) :: box
        integer, intent(in) :: size_wanted
        integer :: cap, k, slot
        cap = 8
        do while (cap < 2 * size_wanted)
            cap = 2 * cap
        end do
        if (allocated(box%table)) deallocate (box%table)
        allocate (box%table(cap))
        box%table = 0
        do k = 1, box%n
            slot = probe(box, box%keys(k))
            box%table(slot) = k
        end do
    end subroutine rebuild_table

    !> Index (1-based, insertion order) of key in a dict, 0 if absent.
    integer function heap_dict_find(self, id, key) result(k)
        class(heap_t), intent(in) :: self
        integer(i8), intent(in) :: id
        type(value_t), intent(in) :: key
        k = self%boxes(id)%table(probe(self%boxes(id), key))
    end function heap_dict_find

    !> d[key] = v (key hashable: the caller checks).
    subroutine heap_dict_set(self, id, key, v)
        class(heap_t), intent(inout) :: self
        integer(i8), intent(in) :: id
        type(value_t), intent(in) :: key, v
        integer :: slot
        type(value_t) :: kcopy, vcopy
        kcopy = key; vcopy = v
        associate (box => self%boxes(id))
            slot = probe(box, kcopy)
            if (box%table(slot) > 0) then
                call move_value(vcopy, box%items(box%table(slot)))
                return
            end if
            call reserve(box, box%n + 1)
            box%n = box%n + 1
            call move_value(kcopy, box%keys(box%n))
            call move_value(vcopy, box%items(box%n))
            if (2 * box%n > size(box%table)) then
                call rebuild_table(box, box%n)
            else
                box%table(slot) = box%n
            end if
        end associate
        self%live_items = self%live_items + 2
    end subroutine heap_dict_set

    !> Removes key k (index in insertion order) of a dict: O(n), the order is kept.
    subroutine heap_dict_delete(self, id, k)
        class(heap_t), intent(inout) :: self
        integer(i8), intent(in) :: id
        integer, intent(in) :: k
        integer :: j
        associate (box => self%boxes(id))
            do j = k, box%n - 1
                call move_value(box%keys(j + 1), box%keys(j))
                call move_value(box%items(j + 1), box%items(j))
            end do
            box%keys(box%n) = value_t()
            box%items(box%n) = value_t()
            box%n = box%n - 1
            call rebuild_table(box, box%n)
        end associate
        self%live_items = self%live_items - 2
    end subroutine heap_dict_delete

    ! ---- values handed out and taken back ---------------------------------------------------

    !> v with every container replaced by a flat copy: a list becomes a flat VK_LIST (i = 0,
    !> items in its tree), a dict with text keys a VK_FACTOR (Code_Aster takes a dict where
    !> a _F goes: `DDL_IMPO=[{'NOEUD': 'N1', 'DX': 0.0}]`). What commands and concept
    !> methods receive.
    !>  message : out, '' or why v cannot be flattened (a dict with other keys, a container
    !>  nested deeper than MAX_FLAT_DEPTH, e.g. a list holding itself)
    recursive subroutine flatten(self, v, flat, message, depth)
        class(heap_t), intent(in) :: self
        type(value_t), intent(in) :: v
        type(value_t), intent(out) :: flat
        character(len=:), allocatable, intent(out) :: message
        integer, intent(in), optional :: depth
        type(value_list_t) :: list
        type(value_t) :: one
        integer :: d, k, n
        message = ''
        d = 0
        if (present(depth)) d = depth
        if (d > MAX_FLAT_DEPTH) then
            message = 'lists or dicts nested more than ' // itoa(MAX_FLAT_DEPTH) // &
                ' deep (does a list contain itself?)'
            return
        end if
        select case (v%kind)
        case (VK_LIST, VK_DICT)
            if (v%i < 1) then                             ! already flat
                flat = v; return
            end if
            n = self%boxes(v%i)%n
            allocate (list%items(n))
            if (v%kind == VK_DICT) allocate (list%keys(n), list%key_line(n), list%key_col(n))
            do k = 1, n
                call flatten(self, self%boxes(v%i)%items(k), list%items(k), message, d + 1)
                if (len(message) > 0) return
                if (v%kind == VK_DICT) then
                    if (self%boxes(v%i)%keys(k)%kind /= VK_STR) then
                        message = 'a dict given where a _F goes needs text keys (keyword ' // &
                            'names), got ' // kind_label(self%boxes(v%i)%keys(k))
                        return
                    end if
                    list%keys(k)%s = self%boxes(v%i)%keys(k)%s
                    list%key_line(k) = v%line; list%key_col(k) = v%col
                end if
            end do
            if (v%kind == VK_DICT) then
                flat = pack_values(VK_FACTOR, list)
            else
                flat = pack_values(VK_LIST, list)
            end if
        case (VK_TUPLE, VK_FACTOR)
            flat = v
            if (.not. allocated(v%tree)) return
            if (.not. any(v%tree%kind == VK_LIST .or. v%tree%kind == VK_DICT)) return
            list = unpack_value(v)
            do k = 1, size(list%items)
                call flatten(self, list%items(k), one, message, d + 1)
                if (len(message) > 0) return
                list%items(k) = one
            end do
            flat = pack_values(v%kind, list)
            if (allocated(v%s)) flat%s = v%s        ! a tag (SIMP(...), a rule: deck_interp_macros)
        case default
            flat = v
            return
        end select
        flat%line = v%line; flat%col = v%col
    end subroutine flatten

    !> v with every flat list (a command's or a method's result) made a container of the
    !> heap, at any depth; the inverse of flatten for lists.
    recursive function adopt(self, v) result(w)
        class(heap_t), intent(inout) :: self
        type(value_t), intent(in) :: v
        type(value_t) :: w
        type(value_list_t) :: list
        integer :: k
        select case (v%kind)
        case (VK_LIST)
            if (v%i > 0) then                                 ! already a container
                w = v; return
            end if
            list = unpack_value(v)
            do k = 1, size(list%items)
                list%items(k) = adopt(self, list%items(k))
            end do
            w = self%new_list(list%items)
        case (VK_TUPLE, VK_FACTOR)                            ! a _F: a dict's lists too
            w = v
            if (.not. allocated(v%tree)) return
            if (.not. any(v%tree%kind == VK_LIST)) return
            list = unpack_value(v)
            do k = 1, size(list%items)
                list%items(k) = adopt(self, list%items(k))
            end do
            w = pack_values(v%kind, list)
            if (allocated(v%s)) w%s = v%s           ! a tag (deck_interp_macros)
        case default
            w = v
            return
        end select
        w%line = v%line; w%col = v%col
    end function adopt

    pure function itoa(n) result(text)
        integer, intent(in) :: n
        character(len=:), allocatable :: text
        character(len=12) :: buf
        write (buf, '(i0)') n
        text = trim(buf)
    end function itoa

    ! ---- collection -------------------------------------------------------------------------

    !> Marks the containers value v refers to, at any depth (a root of the collection).
    subroutine heap_mark(self, v)
        class(heap_t), intent(inout) :: self
        type(value_t), intent(in) :: v
        integer :: id, k
        if (.not. allocated(self%boxes)) return
        call push_refs(v)
        do while (self%nstack > 0)
            id = self%stack(self%nstack)
            self%nstack = self%nstack - 1
            associate (box => self%boxes(id))
                do k = 1, box%n
                    call push_refs(box%items(k))
                    if (box%kind == VK_DICT) call push_refs(box%keys(k))
                end do
            end associate
        end do
    contains
        subroutine push_refs(x)
            type(value_t), intent(in) :: x
            integer :: j
            if (x%kind == VK_LIST .or. x%kind == VK_DICT) call push(x%i)
            if (.not. allocated(x%tree)) return
            do j = 1, size(x%tree)
                if (x%tree(j)%kind == VK_LIST .or. x%tree(j)%kind == VK_DICT) &
                    call push(x%tree(j)%i)
            end do
        end subroutine push_refs
        subroutine push(ref)
            integer(i8), intent(in) :: ref
            integer, allocatable :: bigger(:)
            if (ref < 1 .or. ref > self%nbox) return
            if (self%boxes(ref)%kind == 0 .or. self%boxes(ref)%marked) return
            self%boxes(ref)%marked = .true.
            if (self%nstack == size(self%stack)) then
                allocate (bigger(2 * size(self%stack)))
                bigger(1:self%nstack) = self%stack(1:self%nstack)
                call move_alloc(bigger, self%stack)
            end if
            self%nstack = self%nstack + 1
            self%stack(self%nstack) = int(ref)
        end subroutine push
    end subroutine heap_mark

    !> Frees every container not marked since the last sweep, and clears the marks.
    subroutine heap_sweep(self)
        class(heap_t), intent(inout) :: self
        integer :: id
        integer, allocatable :: bigger(:)
        if (.not. allocated(self%boxes)) return
        do id = 1, self%nbox
            associate (box => self%boxes(id))
                if (box%kind == 0) cycle
                if (box%marked) then
                    box%marked = .false.
                    cycle
                end if
                self%live_items = self%live_items - box%n
                if (box%kind == VK_DICT) self%live_items = self%live_items - box%n
                box%kind = 0; box%n = 0
                if (allocated(box%items)) deallocate (box%items)
                if (allocated(box%keys)) deallocate (box%keys)
                if (allocated(box%table)) deallocate (box%table)
            end associate
            if (self%nfree == size(self%free)) then
                allocate (bigger(2 * size(self%free)))
                bigger(1:self%nfree) = self%free(1:self%nfree)
                call move_alloc(bigger, self%free)
            end if
            self%nfree = self%nfree + 1
            self%free(self%nfree) = id
        end do
        self%items_at_last_sweep = self%live_items
    end subroutine heap_sweep

    !> True when the live containers hold more than MAX_LIVE_ITEMS items.
    pure logical function heap_over_limit(self)
        class(heap_t), intent(in) :: self
        heap_over_limit = self%live_items > MAX_LIVE_ITEMS
    end function heap_over_limit

end module deck_heap
